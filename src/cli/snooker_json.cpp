// `judge` for snooker (docs/cli.md, "judge: snooker and three-cushion"): the document's state
// and options read with every check of the contract, the verdict written in its key order.
#include <fmt/format.h>

#include <array>
#include <string>
#include <string_view>

#include "cli/commands.hpp"
#include "cli/events_input.hpp"
#include "cli/games_json.hpp"
#include "cli/json_out.hpp"
#include "cli/physics_input.hpp"
#include "rules/names.hpp"
#include "rules/snooker.hpp"

namespace cli {

namespace {

namespace ball = physics::snooker_ball;
using nlohmann::ordered_json;

constexpr std::array<std::string_view, 8> kFoulNames{
    "in_off",           "cue_ball_off_table",    "no_contact",
    "wrong_ball_first", "ball_not_on_potted",    "ball_off_table",
    "push_stroke",      "snookered_by_free_ball"};
constexpr std::array<std::string_view, 8> kBallOnNames{"red",   "colour", "yellow", "green",
                                                       "brown", "blue",   "pink",   "black"};
constexpr int kMaxScore = 10000;

std::string colour_name(int id) {
    return std::string(kBallOnNames[static_cast<std::size_t>(id - ball::yellow + 2)]);
}

rules::SnookerOptions read_options(const JsonIn& in) {
    in.expect_object({"miss_rule"});
    rules::SnookerOptions o;
    if (auto v = in.find("miss_rule")) o.miss_rule = v->boolean();
    return o;
}

std::set<int> read_on_table(const JsonIn& in) {
    if (in.array_size() == 0) in.fail("the table is empty: the frame is over, nothing to judge");
    std::set<int> on;
    for (std::size_t i = 0; i < in.array_size(); ++i) {
        const int id = static_cast<int>(in.at(i).integer_in(1, ball::black));
        if (!on.insert(id).second) in.at(i).fail(fmt::format("ball {} is given twice", id));
    }
    return on;
}

// The checks that tie the state's fields together.
void check_state(const JsonIn& in, const rules::SnookerState& s) {
    if (s.nominated) {
        const JsonIn f = in.at("nominated");
        if (!s.has(*s.nominated)) f.fail(fmt::format("ball {} is not on the table", *s.nominated));
        if (!s.colour_on && !s.free_ball)
            f.fail("a ball is nominated only when a colour is on or for a free ball");
        if (s.colour_on && !physics::is_colour(*s.nominated))
            f.fail("with a colour on, nominate a colour (16 yellow to 21 black)");
    }
    if (s.colour_on && s.free_ball)
        in.at("free_ball").fail("a free ball is taken after a foul, when a colour is not on");
    if (s.free_ball && !s.nominated) in.at("free_ball").fail("nominate the free ball");
    if (s.respotted_black && s.on_table != std::set<int>{ball::black})
        in.at("respotted_black").fail("the re-spotted black is played with the black alone");
    if (s.colour_on && s.respotted_black)
        in.at("colour_on").fail("no colour is on on the re-spotted black");
}

rules::SnookerState read_state(const JsonIn& in, const physics::Table& table,
                               const physics::Params& params) {
    in.require_fields(
        {"shooter", "on_table", "cue_ball"},
        {"colour_on", "nominated", "free_ball", "respotted_black", "scores", "break", "positions"});
    rules::SnookerState s;
    s.shooter = in.at("shooter").name_of<rules::Player>();
    s.on_table = read_on_table(in.at("on_table"));
    s.cue_ball = in.at("cue_ball").one_of({"on_table", "in_hand"}) == "on_table"
                     ? rules::CueBall::on_table
                     : rules::CueBall::in_hand;
    if (auto v = in.find("colour_on")) s.colour_on = v->boolean();
    if (auto v = in.find("nominated"); v && !v->is_null())
        s.nominated = static_cast<int>(v->integer_in(1, ball::black));
    if (auto v = in.find("free_ball")) s.free_ball = v->boolean();
    if (auto v = in.find("respotted_black")) s.respotted_black = v->boolean();
    if (auto v = in.find("scores")) s.scores = read_pair(*v, 0, kMaxScore);
    if (auto v = in.find("break")) s.break_points = static_cast<int>(v->integer_in(0, kMaxScore));
    if (auto v = in.find("misses")) s.misses = static_cast<int>(v->integer_in(0, 2));
    check_state(in, s);
    if (auto v = in.find("positions")) {
        const BallSet set{ball::black, [&](int id) { return id == 0 || s.has(id); }};
        s.positions = read_positions(*v, set, table, params);
        const auto cue = s.positions.find(0);
        // A cue ball in hand is judged where the striker placed it: in the D.
        if (cue != s.positions.end() && s.cue_ball == rules::CueBall::in_hand &&
            !physics::snooker_markings(table).in_d(cue->second))
            v->at("0").fail("a cue ball in hand is placed in the D");
    }
    return s;
}

ordered_json state_to_json(const rules::SnookerState& s) {
    ordered_json j;
    j["shooter"] = std::string(rules::name(s.shooter));
    j["on_table"] = s.on_table;
    j["cue_ball"] = s.cue_ball == rules::CueBall::on_table ? "on_table" : "in_hand";
    j["colour_on"] = s.colour_on;
    j["nominated"] = s.nominated ? ordered_json(*s.nominated) : ordered_json(nullptr);
    j["free_ball"] = s.free_ball;
    j["respotted_black"] = s.respotted_black;
    j["scores"] = pair_to_json(s.scores);
    j["break"] = s.break_points;
    j["misses"] = s.misses;
    j["positions"] = positions_to_json(s.positions);
    return j;
}

ordered_json player_or_null(const std::optional<rules::Player>& p) {
    return p ? ordered_json(std::string(rules::name(*p))) : ordered_json(nullptr);
}

ordered_json verdict_to_json(const rules::SnookerVerdict& v) {
    ordered_json j;
    j["foul"] = v.foul;
    ordered_json fouls = ordered_json::array();
    for (rules::SnookerFoul f : v.fouls) fouls.push_back(kFoulNames[static_cast<std::size_t>(f)]);
    j["fouls"] = fouls;
    j["foul_points"] = v.foul_points;
    j["points_scored"] = v.points_scored;
    j["next_shooter"] = player_or_null(v.next_shooter);
    ordered_json respotted = ordered_json::array();
    for (const rules::Respot& r : v.respotted)
        respotted.push_back({{"ball", r.ball},
                             {"spot", r.spot ? ordered_json(colour_name(*r.spot)) : "near_own"},
                             {"pos", to_json(r.pos)}});
    j["respotted"] = respotted;
    j["ball_on"] = v.frame_over ? ordered_json(nullptr)
                                : ordered_json(kBallOnNames[static_cast<std::size_t>(v.ball_on)]);
    j["free_ball"] = v.free_ball;
    j["touching_ball"] = v.touching_ball ? ordered_json(*v.touching_ball) : ordered_json(nullptr);
    j["miss"] = v.miss;
    j["misses"] = v.misses;
    j["may_ask_to_play_again"] = v.may_ask_to_play_again;
    j["frame_over"] = v.frame_over;
    j["winner"] = player_or_null(v.winner);
    j["respotted_black"] = v.respotted_black;
    j["scores"] = pair_to_json(v.state.scores);
    j["state"] = state_to_json(v.state);
    return j;
}

}  // namespace

ordered_json snooker_judge_document(const JsonIn& in) {
    in.require_fields({"game", "state", "events"}, {"table", "options"});
    const physics::Params params = *physics::params_preset("snooker");
    physics::TableSpec spec = *physics::table_preset("snooker12ft");
    if (auto t = in.find("table")) spec = read_table(*t, params.ball_radius);
    if (!spec.pockets) in.at("table").fail("snooker needs a table with pockets");
    rules::SnookerOptions options;
    if (auto o = in.find("options")) options = read_options(*o);
    const physics::Table table = physics::build_table(spec);
    const rules::SnookerState state = read_state(in.at("state"), table, params);
    const BallSet set{ball::black, [&](int id) { return id == 0 || state.has(id); }};
    const std::vector<physics::Event> events = read_events(in.at("events"), set);
    const rules::SnookerTable t{physics::snooker_markings(table), params.ball_radius};
    return verdict_to_json(rules::judge_snooker(options, t, state, events));
}

rules::SnookerOptions read_snooker_options(const JsonIn& in) {
    return read_options(in);
}

rules::SnookerState read_snooker_state(const JsonIn& in, const physics::Table& table,
                                       const physics::Params& params) {
    return read_state(in, table, params);
}

ordered_json snooker_state_json(const rules::SnookerState& s) {
    return state_to_json(s);
}

ordered_json snooker_verdict_json(const rules::SnookerVerdict& v) {
    return verdict_to_json(v);
}

}  // namespace cli
