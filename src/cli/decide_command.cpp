// `decide` (docs/cli.md): the computer player's decision in one position. Reading the game,
// table, options and state is rules_json's (the same checks as `judge`), plus what the AI needs:
// a position for every ball on the table; the planning is src/ai's.
#include <fmt/format.h>

#include <chrono>
#include <cstdint>
#include <set>

#include "ai/ai.hpp"
#include "cli/commands.hpp"
#include "cli/decide_input.hpp"
#include "cli/json_in.hpp"
#include "cli/json_out.hpp"
#include "cli/physics_input.hpp"
#include "cli/rules_json.hpp"
#include "game/state_json.hpp"
#include "physics/params.hpp"
#include "physics/table.hpp"
#include "rules/names.hpp"

namespace cli {

namespace {

constexpr double max_noise = 100.0;

std::optional<rules::Choice> read_choice(const JsonIn& in) {
    if (in.is_null()) return std::nullopt;
    in.expect_object({"by", "options"});
    rules::Choice c;
    JsonIn by = in.at("by");
    const std::string who = by.string();
    std::optional<rules::Player> p = rules::parse<rules::Player>(who);
    if (!p) by.fail(fmt::format("unknown player \"{}\" (expected \"A\" or \"B\")", who));
    c.by = *p;
    JsonIn options = in.at("options");
    const std::size_t n = options.array_size();
    if (n == 0) options.fail("a choice needs at least one option");
    std::set<rules::ChoiceOption> seen;
    for (std::size_t i = 0; i < n; ++i) {
        JsonIn item = options.at(i);
        const std::string name = item.string();
        std::optional<rules::ChoiceOption> o = rules::parse<rules::ChoiceOption>(name);
        if (!o) {
            std::string list;
            for (std::string_view v : rules::EnumNames<rules::ChoiceOption>::names)
                list += fmt::format("{}\"{}\"", list.empty() ? "" : ", ", v);
            item.fail(fmt::format("unknown option \"{}\" (expected one of {})", name, list));
        }
        if (!seen.insert(*o).second) item.fail(fmt::format("\"{}\" is listed twice", name));
        c.options.push_back(*o);
    }
    return c;
}

nlohmann::ordered_json call_json(const rules::Call& c) {
    return game::to_json(c);
}

}  // namespace

nlohmann::ordered_json decide_command(const nlohmann::json& input) {
    using clock = std::chrono::steady_clock;
    JsonIn in(input, "");
    in.expect_object(
        {"game", "table", "options", "state", "choice", "level", "noise", "seed", "after_foul"});
    // Snooker and three-cushion have their own schema (games_decide.cpp).
    const JsonIn game_in = in.at("game");
    if (game_in.raw() == "snooker") return snooker_decide_document(in);
    if (game_in.raw() == "three_cushion") return carom_decide_document(in);
    if (auto a = in.find("after_foul"))
        a->fail("\"after_foul\" is snooker's choice after a foul: use \"choice\" in pool");
    const rules::Game game = read_game(game_in);
    const physics::Params params;
    physics::TableSpec spec = *physics::table_preset("9ft");
    if (auto t = in.find("table")) {
        spec = read_table(*t, params.ball_radius);
        if (!spec.bounded || !spec.pockets)
            t->fail(
                "the AI plays on a table with cushions and pockets: use \"7ft\", \"8ft\", "
                "\"9ft\" or an object with \"pockets\": true");
    }
    rules::Options options;
    if (auto o = in.find("options")) options = read_options(*o);
    ai::Position pos;
    pos.table = physics::build_table(spec);
    pos.params = params;
    pos.ruleset = rules::Ruleset{game, options, {spec.length, spec.width, params.ball_radius}};
    JsonIn state = in.at("state");
    pos.state = read_state(state, game, pos.table, params);
    require_positions(state, pos.state);
    if (ai::cue_in_hand(pos.state)) pos.state.positions.erase(0);  // the AI places it
    if (auto c = in.find("choice")) pos.choice = read_choice(*c);

    ai::PlanSettings settings;
    if (auto l = in.find("level")) settings.level = static_cast<int>(l->integer_in(1, 5));
    if (auto n = in.find("noise")) settings.noise = n->number_in(0.0, max_noise);
    std::uint64_t seed = 1;
    if (auto s = in.find("seed")) seed = s->unsigned_integer();

    const auto start = clock::now();
    const ai::Plan plan = ai::plan(pos, settings, seed);
    const double seconds = std::chrono::duration<double>(clock::now() - start).count();

    const game::Decision& d = plan.decision;
    nlohmann::ordered_json out;
    out["stroke"] = d.choice ? nlohmann::ordered_json(nullptr) : game::to_json(d.stroke);
    out["call"] = d.choice ? nlohmann::ordered_json(nullptr) : call_json(d.call);
    out["cue_pos"] = d.cue_pos ? to_json(*d.cue_pos) : nlohmann::ordered_json(nullptr);
    out["push_out"] = d.push_out;
    out["choice"] =
        d.choice ? nlohmann::ordered_json(rules::name(*d.choice)) : nlohmann::ordered_json(nullptr);
    out["expected_success"] = plan.expected_success;
    out["simulations"] = plan.simulations;
    out["seconds"] = seconds;
    return out;
}

}  // namespace cli
