// `decide` for snooker and three-cushion (docs/cli.md, "decide: snooker and three-cushion"): the
// state read with judge's checks, plus what the AI needs (every ball's position); the planning
// is src/ai's (ai/games.hpp).
#include <fmt/format.h>

#include <chrono>

#include "ai/games.hpp"
#include "cli/commands.hpp"
#include "cli/decide_input.hpp"
#include "cli/games_json.hpp"
#include "cli/json_out.hpp"
#include "cli/physics_input.hpp"
#include "game/state_json.hpp"
#include "physics/markings.hpp"

namespace cli {

namespace {

using nlohmann::ordered_json;
constexpr double max_noise = 100.0;

ai::PlanSettings read_settings(const JsonIn& in) {
    ai::PlanSettings settings;
    if (auto l = in.find("level")) settings.level = static_cast<int>(l->integer_in(1, 5));
    if (auto n = in.find("noise")) settings.noise = n->number_in(0.0, max_noise);
    return settings;
}

std::uint64_t read_decide_seed(const JsonIn& in) {
    if (auto s = in.find("seed")) return s->unsigned_integer();
    return 1;
}

std::string_view kind_name(ai::Kind k) {
    switch (k) {
        case ai::Kind::pot:
            return "pot";
        case ai::Kind::safety:
            return "safety";
        case ai::Kind::kick:
            return "kick";
        default:
            return "other";
    }
}

std::string_view after_foul_name(rules::AfterFoul c) {
    return c == rules::AfterFoul::play         ? "play"
           : c == rules::AfterFoul::play_again ? "play_again"
                                               : "replace";
}

// The choice after a foul: "state" is the verdict's (the incoming player to play), "after_foul"
// the state the foul was played from, whether a miss was called and the offender's misses.
ordered_json after_foul_document(const JsonIn& in, const ai::SnookerPosition& pos,
                                 const ai::PlanSettings& settings) {
    const JsonIn a = in.at("after_foul");
    a.require_fields({"before"}, {"miss", "misses"});
    rules::SnookerVerdict v;
    v.foul = true;
    v.may_ask_to_play_again = true;
    v.state = pos.state;
    if (auto m = a.find("miss")) v.miss = m->boolean();
    if (auto m = a.find("misses")) v.misses = static_cast<int>(m->integer_in(0, 2));
    const rules::SnookerState before = read_snooker_state(a.at("before"), pos.table, pos.params);
    if (before.shooter == pos.state.shooter)
        a.at("before").at("shooter").fail(
            "the state before the foul is the offender's: the "
            "other player than \"state\"'s shooter");
    const rules::AfterFoul c = ai::choose_after_foul(pos, v, before, settings);
    ordered_json out;
    out["after_foul"] = std::string(after_foul_name(c));
    return out;
}

}  // namespace

ordered_json snooker_decide_document(const JsonIn& in) {
    using clock = std::chrono::steady_clock;
    in.require_fields({"game", "state"},
                      {"table", "options", "level", "noise", "seed", "after_foul"});
    const physics::Params params = *physics::params_preset("snooker");
    physics::TableSpec spec = *physics::table_preset("snooker12ft");
    if (auto t = in.find("table")) spec = read_table(*t, params.ball_radius);
    if (!spec.pockets || !spec.bounded)
        in.at("table").fail("snooker needs a table with cushions and pockets");
    rules::SnookerOptions options;
    if (auto o = in.find("options")) options = read_snooker_options(*o);
    const physics::Table table = physics::build_table(spec);
    const JsonIn state = in.at("state");
    rules::SnookerState s = read_snooker_state(state, table, params);
    require_positions(state, s);
    if (s.cue_ball == rules::CueBall::in_hand) s.positions.erase(0);  // the AI places it
    const ai::SnookerPosition pos = ai::snooker_position(table, params, options, s);
    const ai::PlanSettings settings = read_settings(in);
    const auto start = clock::now();
    if (in.find("after_foul")) {
        ordered_json out = after_foul_document(in, pos, settings);
        out["seconds"] = std::chrono::duration<double>(clock::now() - start).count();
        return out;
    }
    const ai::SnookerPlan plan = ai::plan_snooker(pos, settings, read_decide_seed(in));
    const double seconds = std::chrono::duration<double>(clock::now() - start).count();
    ordered_json out;
    out["stroke"] = game::to_json(plan.stroke);
    out["nominated"] = plan.nominated ? ordered_json(*plan.nominated) : ordered_json(nullptr);
    out["cue_pos"] = plan.cue_pos ? to_json(*plan.cue_pos) : ordered_json(nullptr);
    out["kind"] = std::string(kind_name(plan.kind));
    out["expected_success"] = plan.expected_success;
    out["expected_value"] = plan.expected_value;
    out["simulations"] = plan.simulations;
    out["seconds"] = seconds;
    return out;
}

ordered_json carom_decide_document(const JsonIn& in) {
    using clock = std::chrono::steady_clock;
    in.require_fields({"game", "state"}, {"table", "options", "level", "noise", "seed"});
    const physics::Params params = *physics::params_preset("carom");
    physics::TableSpec spec = *physics::table_preset("carom10ft");
    if (auto t = in.find("table")) spec = read_table(*t, params.ball_radius);
    if (spec.pockets || !spec.bounded)
        in.at("table").fail("three-cushion is played on a table with cushions and no pockets");
    rules::CaromOptions options;
    if (auto o = in.find("options")) options = read_carom_options(*o);
    const physics::Table table = physics::build_table(spec);
    const JsonIn state = in.at("state");
    const rules::CaromState s = read_carom_state(state, options, table, params);
    if (s.positions.size() != 3)
        throw BadInput(state.path() + ".positions",
                       "give the three balls' positions: \"0\" white, \"1\" yellow, \"2\" red");
    const ai::PlanSettings settings = read_settings(in);
    const auto start = clock::now();
    const ai::CaromPlan plan =
        ai::plan_three_cushion({options, table, params, s}, settings, read_decide_seed(in));
    ordered_json out;
    out["stroke"] = game::to_json(plan.stroke);
    out["stroke"]["ball"] = plan.stroke.ball;  // the shooter's cue ball: 0 white or 1 yellow
    out["expected_success"] = plan.expected_success;
    out["expected_value"] = plan.expected_value;
    out["simulations"] = plan.simulations;
    out["seconds"] = std::chrono::duration<double>(clock::now() - start).count();
    return out;
}

}  // namespace cli
