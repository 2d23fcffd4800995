// `judge` (docs/cli.md): a game's state before a shot + the shot's events → the verdict and
// the state before the next shot. Reading and writing live in rules_json; the rules in src/rules.
#include <vector>

#include "cli/commands.hpp"
#include "cli/json_in.hpp"
#include "cli/physics_input.hpp"
#include "cli/rules_json.hpp"
#include "physics/params.hpp"
#include "physics/table.hpp"
#include "rules/judge.hpp"
#include "rules/names.hpp"

namespace cli {

namespace {

// The output document in the contract's field order.
nlohmann::ordered_json judge_document(const nlohmann::json& input) {
    JsonIn in(input, "");
    in.expect_object({"game", "table", "options", "state", "events"});
    // The pool games share one schema; snooker and three-cushion have their own.
    const JsonIn game_in = in.at("game");
    if (game_in.raw() == "snooker") return snooker_judge_document(in);
    if (game_in.raw() == "three_cushion") return carom_judge_document(in);
    if (game_in.raw().is_string() && !rules::parse<rules::Game>(game_in.string()))
        game_in.fail("unknown value \"" + game_in.string() +
                     "\" (expected one of \"8ball\", \"9ball\", \"snooker\", \"three_cushion\")");
    const rules::Game game = read_game(game_in);
    const physics::Params params;  // the rules need only the ball radius
    physics::TableSpec spec = *physics::table_preset("9ft");
    if (auto t = in.find("table")) spec = read_table(*t, params.ball_radius);
    rules::Options options;
    if (auto o = in.find("options")) options = read_options(*o);
    const physics::Table table = physics::build_table(spec);
    const rules::GameState state = read_state(in.at("state"), game, table, params);
    const std::vector<physics::Event> events = read_events(in.at("events"), game, state);

    const rules::Ruleset ruleset{game, options, {spec.length, spec.width, params.ball_radius}};
    return to_json(rules::judge(ruleset, state, events));
}

}  // namespace

nlohmann::ordered_json judge_command(const nlohmann::json& input) {
    return judge_document(input);
}

}  // namespace cli
