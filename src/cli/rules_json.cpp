#include "cli/rules_json.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <string_view>

#include "cli/json_out.hpp"
#include "cli/physics_input.hpp"
#include "game/state_json.hpp"
#include "physics/layout.hpp"
#include "rules/names.hpp"

namespace cli {

namespace {

using rules::name;

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr std::int64_t max_fouls_in_row = 1000;

/// A string naming a value of a rules enum (names.hpp).
template <typename E>
E read_enum(const JsonIn& in) {
    std::string s = in.string();
    if (std::optional<E> e = rules::parse<E>(s)) return *e;
    std::string list;
    for (std::string_view n : rules::EnumNames<E>::names)
        list += fmt::format("{}\"{}\"", list.empty() ? "" : ", ", n);
    in.fail(fmt::format("unknown value \"{}\" (expected one of {})", s, list));
}

int read_pocket(const JsonIn& in) {
    std::string s = in.string();
    if (std::optional<int> p = physics::pocket_from_name(s)) return *p;
    in.fail(
        fmt::format("unknown pocket \"{}\" (expected one of \"SW\", \"S\", \"SE\", \"NW\", "
                    "\"N\", \"NE\")",
                    s));
}

int read_rail(const JsonIn& in) {
    std::string s = in.string();
    for (int r = 0; r < 6; ++r)
        if (physics::rail_name(r) == s) return r;
    in.fail(
        fmt::format("unknown cushion \"{}\" (expected one of \"W\", \"E\", \"SW-S\", "
                    "\"S-SE\", \"NW-N\", \"N-NE\")",
                    s));
}

/// A ball id of the game: 0 (the cue ball) when `cue_ok`, else an object ball.
int read_ball_id(const JsonIn& in, rules::Game game, bool cue_ok) {
    const int highest = rules::highest_ball(game);
    const int id = static_cast<int>(in.integer());
    if (id < (cue_ok ? 0 : 1) || id > highest)
        in.fail(fmt::format("unknown ball {}: the {}balls of {} are {} to {}", id,
                            cue_ok ? "" : "object ", rules::name(game), cue_ok ? 0 : 1, highest));
    return id;
}

/// {"A": ..., "B": ...} with both players.
template <typename Read>
auto read_per_player(const JsonIn& in, Read read) {
    in.expect_object({"A", "B"});
    return std::array{read(in.at("A")), read(in.at("B"))};
}

std::optional<rules::Group> read_groups(const JsonIn& in) {
    if (in.is_null()) return std::nullopt;
    auto g = read_per_player(in, [](const JsonIn& v) { return read_enum<rules::Group>(v); });
    if (g[0] == g[1])
        in.fail(
            "the players must have different groups (one \"solids\", one \"stripes\"), or "
            "use null for an open table");
    return g[0];
}

std::set<int> read_on_table(const JsonIn& in, rules::Game game) {
    std::set<int> ids;
    for (std::size_t i = 0; i < in.array_size(); ++i) {
        JsonIn item = in.at(i);
        int id = static_cast<int>(item.integer());
        if (id == 0) item.fail("the cue ball is not listed here: `cue_ball` says where it is");
        id = read_ball_id(item, game, false);
        if (!ids.insert(id).second) item.fail(fmt::format("ball {} is listed twice", id));
    }
    const int key_ball = game == rules::Game::eight_ball ? 8 : 9;
    if (!ids.count(key_ball))
        in.fail(fmt::format("the {} must be on the table: without it the game is over", key_ball));
    return ids;
}

rules::Call read_call(const JsonIn& in, rules::Game game, const rules::GameState& s) {
    if (in.is_null()) return rules::Call::nothing();
    if (game == rules::Game::nine_ball) in.fail("9-ball has no calls: use null");
    if (s.shot == rules::Shot::break_shot) in.fail("nothing is called on the break: use null");
    if (in.raw().is_string()) {
        if (in.string() != "safety")
            in.fail(
                fmt::format("unknown call \"{}\" (expected null, \"safety\" or "
                            "{{\"ball\": 5, \"pocket\": \"N\"}})",
                            in.string()));
        return rules::Call::safety();
    }
    if (!in.raw().is_object())
        in.fail("expected null, \"safety\" or {\"ball\": 5, \"pocket\": \"N\"}");
    in.expect_object({"ball", "pocket"});
    JsonIn ball = in.at("ball");
    const int id = read_ball_id(ball, game, false);
    if (!s.has(id)) ball.fail(fmt::format("ball {} is not on the table", id));
    if (id == 8 && !rules::on_the_eight(s))
        ball.fail("the 8 can be called only once the shooter's group is cleared");
    return rules::Call::ball_in(id, read_pocket(in.at("pocket")));
}

/// A positions key: a ball id written as a plain decimal integer.
std::optional<int> id_from_key(const std::string& key) {
    if (key.empty() || key.size() > 2) return std::nullopt;
    if (!std::all_of(key.begin(), key.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return std::nullopt;
    if (key.size() == 2 && key[0] == '0') return std::nullopt;
    return std::stoi(key);
}

std::map<int, physics::Vec2> read_positions(const JsonIn& in, rules::Game game,
                                            const rules::GameState& s, const physics::Table& table,
                                            const physics::Params& params) {
    if (!in.raw().is_object())
        in.fail("expected an object of positions by ball id, e.g. {\"0\": [0.5, 0.6]}");
    std::map<int, physics::Vec2> positions;
    std::vector<physics::BallState> balls;
    std::vector<std::string> keys;
    for (const auto& [key, value] : in.raw().items()) {
        JsonIn item = in.at(std::string_view(key));
        std::optional<int> id = id_from_key(key);
        if (!id || *id > rules::highest_ball(game))
            item.fail(
                fmt::format("unknown ball id \"{}\": the balls of this game are \"0\" to "
                            "\"{}\"",
                            key, rules::highest_ball(game)));
        if (*id != 0 && !s.has(*id)) item.fail(fmt::format("ball {} is not on the table", *id));
        physics::Vec2 p = read_vec2(item);
        positions[*id] = p;
        physics::BallState b;
        b.id = *id;
        b.pos = p;
        balls.push_back(b);
        keys.push_back(key);
    }
    if (std::optional<physics::LayoutError> e = physics::validate_layout(table, params, balls))
        throw BadInput(fmt::format("{}.{}", in.path(), keys[e->index]), e->message);
    auto cue = positions.find(0);
    if (cue != positions.end() && s.cue_ball == rules::CueBall::in_hand_kitchen &&
        !(cue->second.x < table.length() / 4.0))
        throw BadInput(in.path() + ".0",
                       fmt::format("the cue ball is in hand in the kitchen: place it behind the "
                                   "head string (x < {})",
                                   table.length() / 4.0));
    return positions;
}

std::size_t balls_of(physics::EventType type) {
    return type == physics::EventType::ball_ball ? 2 : 1;
}

/// Per-ball arrays of an event (`pos`, `vel`, `spin`): one entry per ball.
template <typename Read>
void read_per_ball(const JsonIn& event, std::string_view key, std::size_t count, Read read) {
    std::optional<JsonIn> list = event.find(key);
    if (!list) return;
    if (list->array_size() != count)
        list->fail(fmt::format("expected {} entr{}, one per ball of the event", count,
                               count == 1 ? "y" : "ies"));
    for (std::size_t k = 0; k < count; ++k) read(k, list->at(k));
}

physics::Event read_event(const JsonIn& in, const rules::GameState& s, rules::Game game) {
    using physics::EventType;
    in.expect_object({"time", "type", "balls", "pos", "vel", "spin", "speed", "cushion",
                      "pocket_jaw", "pocket", "from", "to"});
    physics::Event e;
    JsonIn type = in.at("type");
    std::string t = type.one_of(
        {"strike", "miscue", "transition", "ball_ball", "cushion", "pocket", "off_table"});
    for (int k = 0; k <= static_cast<int>(EventType::off_table); ++k)
        if (physics::to_string(static_cast<EventType>(k)) == t) e.type = static_cast<EventType>(k);

    JsonIn balls = in.at("balls");
    const std::size_t count = balls_of(e.type);
    if (balls.array_size() != count)
        balls.fail(fmt::format("a {} event has {} ball{}", t, count, count == 1 ? "" : "s"));
    e.ball_count = static_cast<std::uint8_t>(count);
    for (std::size_t k = 0; k < count; ++k) {
        JsonIn item = balls.at(k);
        const int id = read_ball_id(item, game, true);
        if (id != 0 && !s.has(id)) item.fail(fmt::format("ball {} is not on the table", id));
        e.balls[k] = {id, {nan, nan}, {}, {}};
    }
    if (count == 2 && e.balls[0].id == e.balls[1].id)
        balls.fail("a ball_ball event needs two different balls");
    if ((e.type == EventType::strike || e.type == EventType::miscue) && e.balls[0].id != 0)
        balls.at(std::size_t{0}).fail("only the cue ball (0) is struck");

    read_per_ball(in, "pos", count,
                  [&](std::size_t k, const JsonIn& v) { e.balls[k].pos = read_vec2(v); });
    read_per_ball(in, "vel", count,
                  [&](std::size_t k, const JsonIn& v) { e.balls[k].vel = read_vec2(v); });
    read_per_ball(in, "spin", count,
                  [&](std::size_t k, const JsonIn& v) { e.balls[k].spin = read_vec3(v); });
    if (auto time = in.find("time"))
        e.time = time->number_in(0.0, std::numeric_limits<double>::max());
    if (auto speed = in.find("speed"))
        e.speed = speed->number_in(0.0, std::numeric_limits<double>::max());

    std::optional<JsonIn> pocket = in.find("pocket");
    if (e.type == EventType::pocket) {
        e.pocket = read_pocket(in.at("pocket"));
    } else if (pocket) {
        pocket->fail("only a pocket event has a pocket (a jaw of a cushion event is `pocket_jaw`)");
    }
    std::optional<JsonIn> cushion = in.find("cushion"), jaw = in.find("pocket_jaw");
    if ((cushion || jaw) && e.type != EventType::cushion)
        (cushion ? *cushion : *jaw).fail("only a cushion event names a cushion or a pocket jaw");
    if (cushion && jaw) jaw->fail("a cushion event names either a `cushion` or a `pocket_jaw`");
    if (cushion) e.rail = read_rail(*cushion);
    if (jaw) e.pocket = read_pocket(*jaw);

    for (std::string_view key : {"from", "to"}) {
        std::optional<JsonIn> m = in.find(key);
        if (!m) continue;
        if (e.type != EventType::transition) m->fail("only a transition event has `from` and `to`");
        std::optional<physics::Motion> motion = physics::motion_from_string(m->string());
        if (!motion)
            m->fail(
                fmt::format("unknown motion state \"{}\" (expected one of \"stationary\", "
                            "\"spinning\", \"sliding\", \"rolling\", \"pocketed\")",
                            m->string()));
        (key == "from" ? e.from : e.to) = *motion;
    }
    return e;
}

}  // namespace

rules::Game read_game(const JsonIn& in) {
    return read_enum<rules::Game>(in);
}

rules::Options read_options(const JsonIn& in) {
    in.expect_object({"call_shots", "eight_on_break", "foul_ball_in_hand", "scratch_on_eight_loses",
                      "groups_on_break", "rail_after_contact"});
    rules::Options o;
    if (auto v = in.find("call_shots")) o.call_shots = read_enum<rules::CallShots>(*v);
    if (auto v = in.find("eight_on_break")) o.eight_on_break = read_enum<rules::EightOnBreak>(*v);
    if (auto v = in.find("foul_ball_in_hand"))
        o.foul_ball_in_hand = read_enum<rules::FoulBallInHand>(*v);
    if (auto v = in.find("scratch_on_eight_loses")) o.scratch_on_eight_loses = v->boolean();
    if (auto v = in.find("groups_on_break")) o.groups_on_break = v->boolean();
    if (auto v = in.find("rail_after_contact")) o.rail_after_contact = v->boolean();
    return o;
}

rules::GameState read_state(const JsonIn& in, rules::Game game, const physics::Table& table,
                            const physics::Params& params) {
    using rules::Game;
    using rules::Shot;
    in.expect_object({"shooter", "breaker", "shot", "groups", "on_table", "cue_ball", "call",
                      "fouls_in_row", "warned", "positions"});
    rules::GameState s;
    s.shooter = read_enum<rules::Player>(in.at("shooter"));
    s.breaker = read_enum<rules::Player>(in.at("breaker"));
    JsonIn shot = in.at("shot");
    s.shot = read_enum<Shot>(shot);
    s.on_table = read_on_table(in.at("on_table"), game);
    JsonIn cue = in.at("cue_ball");
    s.cue_ball = read_enum<rules::CueBall>(cue);

    if ((s.shot == Shot::push_out || s.shot == Shot::after_push_out) && game == Game::eight_ball)
        shot.fail("a push-out is a 9-ball rule: 8-ball has none");
    if (s.shot == Shot::push_out && s.cue_ball != rules::CueBall::on_table)
        shot.fail(
            "a push-out is allowed only on the shot right after a break without a foul, "
            "with the cue ball where it lies (cue_ball \"on_table\")");
    if (s.shot == Shot::break_shot && s.cue_ball != rules::CueBall::in_hand_kitchen)
        cue.fail("on the break the cue ball is in hand in the kitchen: use \"in_hand_kitchen\"");

    if (auto g = in.find("groups")) {
        s.group_a = read_groups(*g);
        if (s.group_a && game == Game::nine_ball) g->fail("9-ball has no groups: use null");
        if (s.group_a && s.shot == Shot::break_shot)
            g->fail("the table is open on the break: use null");
    }
    if (auto f = in.find("fouls_in_row"))
        s.fouls_in_row = read_per_player(*f, [](const JsonIn& v) {
            return static_cast<int>(v.integer_in(0, max_fouls_in_row));
        });
    if (auto w = in.find("warned"))
        s.warned = read_per_player(*w, [](const JsonIn& v) { return v.boolean(); });
    if (auto c = in.find("call")) s.call = read_call(*c, game, s);
    if (auto p = in.find("positions")) s.positions = read_positions(*p, game, s, table, params);
    return s;
}

std::vector<physics::Event> read_events(const JsonIn& in, rules::Game game,
                                        const rules::GameState& s) {
    std::vector<physics::Event> events;
    const std::size_t n = in.array_size();
    events.reserve(n);
    for (std::size_t i = 0; i < n; ++i) events.push_back(read_event(in.at(i), s, game));
    return events;
}

// The writers are the game module's (game/state_json.hpp): save files and `judge` output share
// one schema.
nlohmann::ordered_json to_json(const rules::GameState& s) {
    return game::to_json(s);
}

nlohmann::ordered_json to_json(const rules::Options& o) {
    return game::to_json(o);
}

nlohmann::ordered_json to_json(const std::optional<rules::Choice>& c) {
    return game::to_json(c);
}

nlohmann::ordered_json to_json(const rules::Verdict& v) {
    return game::to_json(v);
}

}  // namespace cli
