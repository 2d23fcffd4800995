// `judge` for three-cushion (docs/cli.md, "judge: snooker and three-cushion"): the document's
// state and options read with every check of the contract, the verdict in its key order.
#include <array>
#include <string>
#include <string_view>

#include "cli/commands.hpp"
#include "cli/events_input.hpp"
#include "cli/games_json.hpp"
#include "cli/json_out.hpp"
#include "cli/physics_input.hpp"
#include "rules/names.hpp"
#include "rules/three_cushion.hpp"

namespace cli {

namespace {

using nlohmann::ordered_json;

constexpr std::array<std::string_view, 4> kFoulNames{"wrong_cue_ball", "ball_off_table",
                                                     "push_stroke", "red_not_first"};
constexpr int kMaxPoints = 10000;

rules::CaromOptions read_options(const JsonIn& in) {
    in.expect_object({"target", "equal_innings"});
    rules::CaromOptions o;
    if (auto v = in.find("target")) o.target = static_cast<int>(v->integer_in(1, kMaxPoints));
    if (auto v = in.find("equal_innings")) o.equal_innings = v->boolean();
    return o;
}

rules::CaromState read_state(const JsonIn& in, const rules::CaromOptions& o,
                             const physics::Table& table, const physics::Params& params) {
    in.require_fields({"shooter"}, {"starter", "opening", "equalizing", "scores", "innings", "run",
                                    "high_run", "positions"});
    rules::CaromState s;
    s.shooter = in.at("shooter").name_of<rules::Player>();
    s.starter = s.shooter;
    if (auto v = in.find("starter")) s.starter = v->name_of<rules::Player>();
    if (auto v = in.find("opening")) s.opening = v->boolean();
    if (auto v = in.find("equalizing")) s.equalizing = v->boolean();
    if (auto v = in.find("scores")) s.scores = read_pair(*v, 0, o.target - 1);
    if (auto v = in.find("innings")) s.innings = read_pair(*v, 0, kMaxPoints);
    if (auto v = in.find("run")) s.run = static_cast<int>(v->integer_in(0, o.target - 1));
    if (auto v = in.find("high_run")) s.high_run = read_pair(*v, 0, o.target);
    if (s.opening && (s.shooter != s.starter || s.scores != std::array<int, 2>{0, 0}))
        in.at("opening").fail("the opening stroke is the starter's, before any point");
    if (s.equalizing && (!o.equal_innings || s.shooter == s.starter))
        in.at("equalizing")
            .fail("only the second player equalizes, with the equal_innings option on");
    if (auto v = in.find("positions")) {
        const BallSet set{physics::carom_ball::red, [](int) { return true; }, false, true};
        s.positions = read_positions(*v, set, table, params);
    }
    return s;
}

ordered_json player_or_null(const std::optional<rules::Player>& p) {
    return p ? ordered_json(std::string(rules::name(*p))) : ordered_json(nullptr);
}

ordered_json state_to_json(const rules::CaromState& s) {
    ordered_json j;
    j["shooter"] = std::string(rules::name(s.shooter));
    j["starter"] = std::string(rules::name(s.starter));
    j["opening"] = s.opening;
    j["equalizing"] = s.equalizing;
    j["scores"] = pair_to_json(s.scores);
    j["innings"] = pair_to_json(s.innings);
    j["run"] = s.run;
    j["high_run"] = pair_to_json(s.high_run);
    j["positions"] = positions_to_json(s.positions);
    return j;
}

ordered_json verdict_to_json(const rules::CaromVerdict& v) {
    ordered_json j;
    j["point"] = v.point;
    j["foul"] = v.foul;
    ordered_json fouls = ordered_json::array();
    for (rules::CaromFoul f : v.fouls) fouls.push_back(kFoulNames[static_cast<std::size_t>(f)]);
    j["fouls"] = fouls;
    j["cushions"] = v.cushions;
    j["next_shooter"] = player_or_null(v.next_shooter);
    j["scores"] = pair_to_json(v.state.scores);
    j["innings"] = pair_to_json(v.state.innings);
    j["game_over"] = v.game_over;
    j["winner"] = player_or_null(v.winner);
    j["respotted"] = v.respotted;
    j["state"] = state_to_json(v.state);
    return j;
}

}  // namespace

ordered_json carom_judge_document(const JsonIn& in) {
    in.require_fields({"game", "state", "events"}, {"table", "options"});
    const physics::Params params = *physics::params_preset("carom");
    physics::TableSpec spec = *physics::table_preset("carom10ft");
    if (auto t = in.find("table")) spec = read_table(*t, params.ball_radius);
    if (spec.pockets) in.at("table").fail("three-cushion is played on a table without pockets");
    rules::CaromOptions options;
    if (auto o = in.find("options")) options = read_options(*o);
    const physics::Table table = physics::build_table(spec);
    const rules::CaromState state = read_state(in.at("state"), options, table, params);
    const BallSet set{physics::carom_ball::red, [](int) { return true; }, false, true};
    const std::vector<physics::Event> events = read_events(in.at("events"), set);
    return verdict_to_json(rules::judge_three_cushion(options, physics::carom_spots(table),
                                                      params.ball_radius, state, events));
}

rules::CaromOptions read_carom_options(const JsonIn& in) {
    return read_options(in);
}

rules::CaromState read_carom_state(const JsonIn& in, const rules::CaromOptions& o,
                                   const physics::Table& table, const physics::Params& params) {
    return read_state(in, o, table, params);
}

ordered_json carom_state_json(const rules::CaromState& s) {
    return state_to_json(s);
}

ordered_json carom_verdict_json(const rules::CaromVerdict& v) {
    return verdict_to_json(v);
}

}  // namespace cli
