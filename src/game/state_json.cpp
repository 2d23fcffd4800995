#include "game/state_json.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "physics/layout.hpp"
#include "physics/table.hpp"
#include "rules/names.hpp"

namespace game {

using nlohmann::ordered_json;
using rules::name;

namespace {

constexpr std::int64_t max_fouls_in_row = 1000;

ordered_json groups_json(const std::optional<rules::Group>& group_a) {
    if (!group_a) return nullptr;
    return {{"A", name(*group_a)}, {"B", name(rules::other(*group_a))}};
}

template <typename E>
ordered_json optional_name(const std::optional<E>& e) {
    if (!e) return nullptr;
    return name(*e);
}

int key_ball(rules::Game game) {
    return game == rules::Game::eight_ball ? 8 : 9;
}

/// An object ball of the game (or the cue ball, when `cue_ok`).
int read_ball(const Field& f, rules::Game game, bool cue_ok) {
    const int highest = rules::highest_ball(game);
    const std::int64_t id = f.integer();
    if (id < (cue_ok ? 0 : 1) || id > highest) {
        if (id == 0) f.fail("the cue ball (0) is not allowed here: an object ball is expected");
        f.fail(fmt::format("ball {} does not exist (the balls of {} are {} to {})", id, name(game),
                           cue_ok ? 0 : 1, highest));
    }
    return static_cast<int>(id);
}

std::optional<rules::Player> read_optional_player(const Field& f) {
    if (f.is_null()) return std::nullopt;
    return f.name_of<rules::Player>();
}

std::optional<rules::Group> read_groups(const Field& f) {
    if (f.is_null()) return std::nullopt;
    f.require_fields({"A", "B"});
    const rules::Group a = f.at("A").name_of<rules::Group>();
    const rules::Group b = f.at("B").name_of<rules::Group>();
    if (a == b) f.fail("the players must have different groups, or null for an open table");
    return a;
}

template <typename Read>
auto read_per_player(const Field& f, Read read) {
    f.require_fields({"A", "B"});
    return std::array{read(f.at("A")), read(f.at("B"))};
}

std::set<int> read_on_table(const Field& f, rules::Game game, bool finished) {
    std::set<int> ids;
    for (std::size_t i = 0; i < f.array_size(); ++i) {
        Field item = f.at(i);
        if (item.raw().is_number_integer() && item.raw().get<std::int64_t>() == 0)
            item.fail("the cue ball is not listed here: `cue_ball` says where it is");
        const int id = read_ball(item, game, false);
        if (!ids.insert(id).second) item.fail(fmt::format("ball {} is listed twice", id));
    }
    if (!finished && !ids.count(key_ball(game)))
        f.fail(fmt::format("the {} must be on the table while the game is on", key_ball(game)));
    return ids;
}

rules::Call read_call(const Field& f, rules::Game game, const rules::GameState& s) {
    if (f.is_null()) return rules::Call::nothing();
    if (game == rules::Game::nine_ball) f.fail("9-ball has no calls: use null");
    if (s.shot == rules::Shot::break_shot) f.fail("nothing is called on the break: use null");
    if (f.raw().is_string()) {
        if (f.string() != "safety")
            f.fail(fmt::format(
                "unknown call \"{}\" (expected null, \"safety\" or {{\"ball\": 5, \"pocket\": "
                "\"N\"}})",
                f.string()));
        return rules::Call::safety();
    }
    if (!f.raw().is_object())
        f.fail("expected null, \"safety\" or {\"ball\": 5, \"pocket\": \"N\"}");
    f.require_fields({"ball", "pocket"});
    Field ball = f.at("ball");
    const int id = read_ball(ball, game, false);
    if (!s.has(id)) ball.fail(fmt::format("ball {} is not on the table", id));
    if (id == 8 && !rules::on_the_eight(s))
        ball.fail("the 8 can be called only once the shooter's group is cleared");
    return rules::Call::ball_in(id, read_pocket(f.at("pocket")));
}

/// A positions key: a ball id written as a plain decimal integer.
std::optional<int> id_from_key(const std::string& key) {
    if (key.empty() || key.size() > 2) return std::nullopt;
    if (!std::all_of(key.begin(), key.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return std::nullopt;
    if (key.size() == 2 && key[0] == '0') return std::nullopt;
    return std::stoi(key);
}

std::map<int, physics::Vec2> read_positions(const Field& f, const TableContext& t,
                                            const rules::GameState& s, Fields fields) {
    if (!f.raw().is_object())
        f.fail("expected an object of positions by ball id, e.g. {\"0\": [0.5, 0.6]}");
    std::map<int, physics::Vec2> positions;
    std::vector<physics::BallState> balls;
    std::vector<std::string> keys;
    for (const auto& [key, value] : f.raw().items()) {
        Field item = f.at(std::string_view(key));
        std::optional<int> id = id_from_key(key);
        if (!id || *id > rules::highest_ball(t.game))
            item.fail(fmt::format("unknown ball \"{}\": the balls of {} are \"0\" to \"{}\"", key,
                                  name(t.game), rules::highest_ball(t.game)));
        if (*id != 0 && !s.has(*id)) item.fail(fmt::format("ball {} is not on the table", *id));
        const physics::Vec2 p = read_vec2(item);
        positions[*id] = p;
        physics::BallState b;
        b.id = *id;
        b.pos = p;
        balls.push_back(b);
        keys.push_back(key);
    }
    if (fields == Fields::all) {
        for (int id : s.on_table)
            if (!positions.count(id))
                f.fail(fmt::format("ball {} is on the table but has no position", id));
        if (s.cue_ball == rules::CueBall::on_table && !positions.count(0))
            f.fail("the cue ball is on the table but has no position (\"0\")");
    }
    if (std::optional<physics::LayoutError> e = physics::validate_layout(t.table, t.params, balls))
        throw LoadError(f.path() + "." + keys[e->index], e->message);
    auto cue = positions.find(0);
    const double head_string = t.table.length() / 4.0;
    if (cue != positions.end() && s.cue_ball == rules::CueBall::in_hand_kitchen &&
        !(cue->second.x < head_string))
        throw LoadError(f.path() + ".0",
                        fmt::format("the cue ball is in hand in the kitchen: it must lie behind "
                                    "the head string (x < {})",
                                    head_string));
    return positions;
}

std::optional<rules::Choice> read_choice(const Field& f) {
    if (f.is_null()) return std::nullopt;
    f.require_fields({"by", "options"});
    rules::Choice c;
    c.by = f.at("by").name_of<rules::Player>();
    Field options = f.at("options");
    if (options.array_size() == 0) options.fail("a choice offers at least one option");
    for (std::size_t i = 0; i < options.array_size(); ++i) {
        const rules::ChoiceOption o = options.at(i).name_of<rules::ChoiceOption>();
        if (std::find(c.options.begin(), c.options.end(), o) != c.options.end())
            options.at(i).fail(fmt::format("\"{}\" is listed twice", name(o)));
        c.options.push_back(o);
    }
    return c;
}

physics::EventType read_event_type(const Field& f) {
    const std::string t = f.string();
    for (int k = 0; k <= static_cast<int>(physics::EventType::off_table); ++k) {
        const auto type = static_cast<physics::EventType>(k);
        if (physics::to_string(type) == t) return type;
    }
    f.fail(fmt::format(
        "unknown event type \"{}\" (expected one of \"strike\", \"miscue\", \"transition\", "
        "\"ball_ball\", \"cushion\", \"pocket\", \"off_table\")",
        t));
}

physics::Motion read_motion(const Field& f) {
    if (std::optional<physics::Motion> m = physics::motion_from_string(f.string())) return *m;
    f.fail(
        fmt::format("unknown motion state \"{}\" (expected one of \"stationary\", \"spinning\", "
                    "\"sliding\", \"rolling\", \"pocketed\")",
                    f.string()));
}

int read_rail(const Field& f) {
    const std::string s = f.string();
    for (int r = 0; r < 6; ++r)
        if (physics::rail_name(r) == s) return r;
    f.fail(fmt::format(
        "unknown cushion \"{}\" (expected one of \"W\", \"E\", \"SW-S\", \"S-SE\", \"NW-N\", "
        "\"N-NE\")",
        s));
}

}  // namespace

// ---- Writing

ordered_json to_json(physics::Vec2 v) {
    return ordered_json::array({v.x, v.y});
}

ordered_json to_json(physics::Vec3 v) {
    return ordered_json::array({v.x, v.y, v.z});
}

ordered_json to_json(const rules::Call& c) {
    switch (c.kind) {
        case rules::Call::Kind::none:
            return nullptr;
        case rules::Call::Kind::safety:
            return "safety";
        case rules::Call::Kind::ball:
            break;
    }
    return {{"ball", c.ball}, {"pocket", physics::pocket_name(c.pocket)}};
}

ordered_json to_json(const physics::TableSpec& t) {
    return {{"length", t.length},
            {"width", t.width},
            {"corner_mouth", t.corner_mouth},
            {"side_mouth", t.side_mouth},
            {"corner_facing_deg", t.corner_facing_deg},
            {"side_facing_deg", t.side_facing_deg},
            {"jaw_nose_radius", t.jaw_nose_radius},
            {"cushion_height", t.cushion_height},
            {"corner_shelf", t.corner_shelf},
            {"side_shelf", t.side_shelf},
            {"jaw_depth", t.jaw_depth},
            {"pockets", t.pockets}};
}

ordered_json to_json(const physics::Params& p) {
    ordered_json j;
    j["ball_radius"] = p.ball_radius;
    j["ball_mass"] = p.ball_mass;
    j["gravity"] = p.gravity;
    j["mu_slide"] = p.mu_slide;
    j["mu_roll"] = p.mu_roll;
    j["spin_decel"] = p.spin_decel;
    j["e_ball"] = p.e_ball;
    j["mu_ball"] = p.mu_ball ? ordered_json(*p.mu_ball) : ordered_json(nullptr);
    j["e_cushion"] = p.e_cushion;
    j["mu_cushion"] = p.mu_cushion;
    j["cue_mass"] = p.cue_mass;
    j["cue_tip_e"] = p.cue_tip_e;
    j["cue_endmass"] = p.cue_endmass;
    j["miscue_limit"] = p.miscue_limit;
    return j;
}

ordered_json to_json(const rules::GameState& s) {
    ordered_json j;
    j["shooter"] = name(s.shooter);
    j["breaker"] = name(s.breaker);
    j["shot"] = name(s.shot);
    j["groups"] = groups_json(s.group_a);
    j["on_table"] = s.on_table;
    j["cue_ball"] = name(s.cue_ball);
    j["call"] = to_json(s.call);
    j["fouls_in_row"] = {{"A", s.fouls_in_row[0]}, {"B", s.fouls_in_row[1]}};
    j["warned"] = {{"A", s.warned[0]}, {"B", s.warned[1]}};
    ordered_json positions = ordered_json::object();
    for (const auto& [id, p] : s.positions) positions[std::to_string(id)] = to_json(p);
    j["positions"] = std::move(positions);
    return j;
}

ordered_json to_json(const rules::Options& o) {
    return {{"call_shots", name(o.call_shots)},
            {"eight_on_break", name(o.eight_on_break)},
            {"foul_ball_in_hand", name(o.foul_ball_in_hand)},
            {"scratch_on_eight_loses", o.scratch_on_eight_loses},
            {"groups_on_break", o.groups_on_break},
            {"rail_after_contact", o.rail_after_contact}};
}

ordered_json to_json(const std::optional<rules::Choice>& c) {
    if (!c) return nullptr;
    ordered_json options = ordered_json::array();
    for (rules::ChoiceOption o : c->options) options.push_back(name(o));
    return {{"by", name(c->by)}, {"options", std::move(options)}};
}

ordered_json to_json(const rules::Verdict& v) {
    ordered_json j;
    j["foul"] = v.foul;
    ordered_json fouls = ordered_json::array();
    for (rules::Foul f : v.fouls) fouls.push_back(name(f));
    j["fouls"] = std::move(fouls);
    j["turn_passes"] = v.turn_passes;
    j["next_shooter"] = optional_name(v.next_shooter);
    j["ball_in_hand"] = name(v.ball_in_hand);
    j["groups"] = groups_json(v.group_a);
    j["respot"] = ordered_json(v.respot);
    j["choice"] = to_json(v.choice);
    j["game_over"] = v.game_over;
    j["winner"] = optional_name(v.winner);
    j["break"] = name(v.break_result);
    j["state"] = to_json(v.state);
    return j;
}

ordered_json to_json(const physics::Stroke& s) {
    return {{"speed", s.speed},
            {"heading_deg", s.heading_deg},
            {"side", s.side},
            {"top", s.top},
            {"elevation_deg", s.elevation_deg}};
}

ordered_json to_json(const physics::Event& event) {
    using physics::EventType;
    ordered_json e;
    e["time"] = event.time;
    e["type"] = std::string(physics::to_string(event.type));
    ordered_json ids = ordered_json::array();
    for (int k = 0; k < event.ball_count; ++k) ids.push_back(event.ball(k));
    e["balls"] = std::move(ids);
    switch (event.type) {
        case EventType::transition:
            e["from"] = std::string(physics::to_string(event.from));
            e["to"] = std::string(physics::to_string(event.to));
            break;
        case EventType::ball_ball:
            e["speed"] = event.speed;
            break;
        case EventType::cushion:
            e["speed"] = event.speed;
            if (event.rail >= 0)
                e["cushion"] = std::string(physics::rail_name(event.rail));
            else
                e["pocket_jaw"] = std::string(physics::pocket_name(event.pocket));
            break;
        case EventType::pocket:
            e["pocket"] = std::string(physics::pocket_name(event.pocket));
            break;
        case EventType::strike:
        case EventType::miscue:
        case EventType::off_table:
            break;
    }
    ordered_json pos = ordered_json::array(), vel = ordered_json::array(),
                 spin = ordered_json::array();
    for (std::size_t k = 0; k < event.ball_count; ++k) {
        pos.push_back(to_json(event.balls[k].pos));
        vel.push_back(to_json(event.balls[k].vel));
        spin.push_back(to_json(event.balls[k].spin));
    }
    e["pos"] = std::move(pos);
    e["vel"] = std::move(vel);
    e["spin"] = std::move(spin);
    return e;
}

// ---- Reading

physics::Vec2 read_vec2(const Field& f) {
    if (!f.raw().is_array() || f.raw().size() != 2)
        f.fail("expected [x, y]: an array of 2 numbers");
    return {f.at(std::size_t{0}).number(), f.at(std::size_t{1}).number()};
}

physics::Vec3 read_vec3(const Field& f) {
    if (!f.raw().is_array() || f.raw().size() != 3)
        f.fail("expected [x, y, z]: an array of 3 numbers");
    return {f.at(std::size_t{0}).number(), f.at(std::size_t{1}).number(),
            f.at(std::size_t{2}).number()};
}

int read_pocket(const Field& f) {
    const std::string s = f.string();
    if (std::optional<int> p = physics::pocket_from_name(s)) return *p;
    f.fail(fmt::format(
        "unknown pocket \"{}\" (expected one of \"SW\", \"S\", \"SE\", \"NW\", \"N\", \"NE\")", s));
}

namespace {

// The accepted range of a physical parameter: what real tables use, widened by a factor of ten
// or more, and within what the engine represents (a friction of 1e-300 makes the times v/(μg)
// overflow). `zero_ok`: exactly 0 is accepted too (no friction at all, a special case of the
// engine). Pinned by tests/cli/params_range_test.cpp, which runs each end.
struct ParamRange {
    double lo, hi;
    bool zero_ok = false;
};

double read_param(const Field& v, ParamRange r) {
    const double x = v.number();
    if ((r.zero_ok && x == 0.0) || (x >= r.lo && x <= r.hi)) return x;
    v.fail(fmt::format("{} is out of range: must be {}from {} to {}", x, r.zero_ok ? "0 or " : "",
                       r.lo, r.hi));
}

}  // namespace

namespace {

constexpr double max_table_size = 100.0;  // (unit: m) far beyond any table; keeps sums finite

physics::TableSpec preset(const Field& f) {
    const std::string name =
        f.one_of({"7ft", "8ft", "9ft", "snooker12ft", "carom10ft", "unbounded"});
    std::optional<physics::TableSpec> spec = physics::table_preset(name);
    if (!spec) f.fail(fmt::format("the engine has no table preset \"{}\"", name));
    return *spec;
}

// The fields of a table object over `spec`: with `Fields::all` every one must be given.
void read_table_fields(const Field& f, physics::TableSpec& spec, Fields fields) {
    const std::initializer_list<std::string_view> keys = {
        "length",          "width",           "corner_mouth",   "side_mouth",   "corner_facing_deg",
        "side_facing_deg", "jaw_nose_radius", "cushion_height", "corner_shelf", "side_shelf",
        "jaw_depth",       "pockets"};
    if (fields == Fields::all)
        f.require_fields(keys, {"preset"});
    else
        f.require_fields(
            {}, {"preset", "length", "width", "corner_mouth", "side_mouth", "corner_facing_deg",
                 "side_facing_deg", "jaw_nose_radius", "cushion_height", "corner_shelf",
                 "side_shelf", "jaw_depth", "pockets"});
    if (auto p = f.find("preset")) spec = preset(*p);
    auto set = [&](std::string_view key, double& field, auto read) {
        if (std::optional<Field> v = f.find(key)) field = read(*v);
    };
    auto length = [](const Field& v) { return v.positive_up_to(max_table_size); };
    auto depth = [](const Field& v) { return v.number_in(0.0, max_table_size); };
    auto angle = [](const Field& v) {
        const double a = v.number();
        if (!(a > 0.0 && a < 180.0))
            v.fail(fmt::format("{} is out of range: must be between 0 and 180 degrees", a));
        return a;
    };
    set("length", spec.length, length);
    set("width", spec.width, length);
    set("corner_mouth", spec.corner_mouth, length);
    set("side_mouth", spec.side_mouth, length);
    set("corner_facing_deg", spec.corner_facing_deg, angle);
    set("side_facing_deg", spec.side_facing_deg, angle);
    set("jaw_nose_radius", spec.jaw_nose_radius, depth);
    set("cushion_height", spec.cushion_height, length);
    set("corner_shelf", spec.corner_shelf, depth);
    set("side_shelf", spec.side_shelf, depth);
    set("jaw_depth", spec.jaw_depth, length);
    if (auto p = f.find("pockets")) spec.pockets = p->boolean();
}

}  // namespace

physics::TableSpec read_table(const Field& f, double ball_radius, Fields fields) {
    physics::TableSpec spec;
    if (f.raw().is_string() && fields == Fields::required) {
        spec = preset(f);
    } else if (f.raw().is_object()) {
        read_table_fields(f, spec, fields);
    } else {
        f.fail(
            "expected a preset name (\"7ft\", \"8ft\", \"9ft\", \"snooker12ft\", \"carom10ft\", "
            "\"unbounded\") or an object like "
            "{\"preset\": \"9ft\", \"length\": 2.54}");
    }
    if (std::optional<std::string> problem = physics::validate_table_spec(spec, ball_radius)) {
        // The engine's message starts with the field name ("corner_mouth: ..."): point at that
        // field when the document gave it, else at the table as a whole.
        const std::string& message = *problem;
        const auto colon = message.find(": ");
        if (colon != std::string::npos && f.raw().is_object()) {
            const std::string field = message.substr(0, colon);
            if (f.has(field)) f.at(field).fail(message.substr(colon + 2));
        }
        f.fail(fmt::format("{} (for balls of radius R = {} m)", message, ball_radius));
    }
    return spec;
}

physics::Params read_params(const Field& f, Fields fields) {
    const std::initializer_list<std::string_view> keys = {
        "ball_radius", "ball_mass", "gravity",     "mu_slide",    "mu_roll",
        "spin_decel",  "e_ball",    "mu_ball",     "e_cushion",   "mu_cushion",
        "cue_mass",    "cue_tip_e", "cue_endmass", "miscue_limit"};
    if (fields == Fields::all)
        f.require_fields(keys);
    else
        f.expect_object(keys);
    physics::Params p;
    auto set = [&](std::string_view key, double& field, ParamRange range) {
        if (std::optional<Field> v = f.find(key)) field = read_param(*v, range);
    };
    set("ball_radius", p.ball_radius, {0.01, 0.05});
    set("ball_mass", p.ball_mass, {0.01, 10.0});
    set("gravity", p.gravity, {0.1, 100.0});
    set("mu_slide", p.mu_slide, {0.001, 1.0, true});
    set("mu_roll", p.mu_roll, {0.0001, 1.0, true});
    set("spin_decel", p.spin_decel, {0.01, 1000.0});
    set("e_ball", p.e_ball, {0.0, 1.0});
    if (std::optional<Field> v = f.find("mu_ball"))
        p.mu_ball = v->is_null() ? std::nullopt : std::optional(read_param(*v, {0.0, 1.0}));
    set("e_cushion", p.e_cushion, {0.0, 1.0});
    set("mu_cushion", p.mu_cushion, {0.0, 1.0});
    set("cue_mass", p.cue_mass, {0.1, 10.0});
    set("cue_tip_e", p.cue_tip_e, {0.0, 1.0});
    set("cue_endmass", p.cue_endmass, {0.001, 1.0});
    set("miscue_limit", p.miscue_limit, {0.01, 1.0});
    return p;
}

rules::Options read_options(const Field& f, Fields fields) {
    const std::initializer_list<std::string_view> keys = {
        "call_shots",      "eight_on_break",    "foul_ball_in_hand", "scratch_on_eight_loses",
        "groups_on_break", "rail_after_contact"};
    if (fields == Fields::all)
        f.require_fields(keys);
    else
        f.expect_object(keys);
    rules::Options o;
    if (auto v = f.find("call_shots")) o.call_shots = v->name_of<rules::CallShots>();
    if (auto v = f.find("eight_on_break")) o.eight_on_break = v->name_of<rules::EightOnBreak>();
    if (auto v = f.find("foul_ball_in_hand"))
        o.foul_ball_in_hand = v->name_of<rules::FoulBallInHand>();
    if (auto v = f.find("scratch_on_eight_loses")) o.scratch_on_eight_loses = v->boolean();
    if (auto v = f.find("groups_on_break")) o.groups_on_break = v->boolean();
    if (auto v = f.find("rail_after_contact")) o.rail_after_contact = v->boolean();
    return o;
}

namespace {

rules::GameState read_state_impl(const Field& f, const TableContext& t, Fields fields,
                                 bool finished) {
    using rules::Shot;
    const std::initializer_list<std::string_view> required = {"shooter", "breaker", "shot",
                                                              "on_table", "cue_ball"};
    const std::initializer_list<std::string_view> optional = {"groups", "call", "fouls_in_row",
                                                              "warned", "positions"};
    f.require_fields(required, optional);
    if (fields == Fields::all)
        for (std::string_view k : optional) (void)f.at(k);
    rules::GameState s;
    s.shooter = f.at("shooter").name_of<rules::Player>();
    s.breaker = f.at("breaker").name_of<rules::Player>();
    Field shot = f.at("shot");
    s.shot = shot.name_of<Shot>();
    s.on_table = read_on_table(f.at("on_table"), t.game, finished);
    Field cue = f.at("cue_ball");
    s.cue_ball = cue.name_of<rules::CueBall>();
    if ((s.shot == Shot::push_out || s.shot == Shot::after_push_out) &&
        t.game == rules::Game::eight_ball)
        shot.fail("a push-out is a 9-ball rule: 8-ball has none");
    if (s.shot == Shot::push_out && s.cue_ball != rules::CueBall::on_table)
        shot.fail("a push-out is played with the cue ball where it lies (cue_ball \"on_table\")");
    if (s.shot == Shot::break_shot && s.cue_ball != rules::CueBall::in_hand_kitchen)
        cue.fail("on the break the cue ball is in hand in the kitchen: \"in_hand_kitchen\"");
    if (std::optional<Field> groups = f.find("groups")) {
        s.group_a = read_groups(*groups);
        if (s.group_a && t.game == rules::Game::nine_ball)
            groups->fail("9-ball has no groups: use null");
        if (s.group_a && s.shot == Shot::break_shot)
            groups->fail("the table is open on the break: use null");
    }
    if (auto v = f.find("fouls_in_row"))
        s.fouls_in_row = read_per_player(
            *v, [](const Field& n) { return static_cast<int>(n.integer_in(0, max_fouls_in_row)); });
    if (auto v = f.find("warned"))
        s.warned = read_per_player(*v, [](const Field& b) { return b.boolean(); });
    if (auto v = f.find("call")) s.call = read_call(*v, t.game, s);
    if (auto v = f.find("positions")) s.positions = read_positions(*v, t, s, fields);
    return s;
}

}  // namespace

rules::GameState read_state(const Field& f, const TableContext& t, Fields fields, bool finished) {
    return read_state_impl(f, t, fields, finished);
}

rules::Verdict read_verdict(const Field& f, const TableContext& t) {
    f.require_fields({"foul", "fouls", "turn_passes", "next_shooter", "ball_in_hand", "groups",
                      "respot", "choice", "game_over", "winner", "break", "state"});
    rules::Verdict v;
    v.foul = f.at("foul").boolean();
    Field fouls = f.at("fouls");
    for (std::size_t i = 0; i < fouls.array_size(); ++i) {
        const rules::Foul foul = fouls.at(i).name_of<rules::Foul>();
        if (!v.fouls.empty() && !(v.fouls.back() < foul))
            fouls.at(i).fail("fouls are listed once each, in the canonical order");
        v.fouls.push_back(foul);
    }
    if (v.foul != !v.fouls.empty())
        f.at("foul").fail("must be true exactly when `fouls` lists a foul");
    v.turn_passes = f.at("turn_passes").boolean();
    v.next_shooter = read_optional_player(f.at("next_shooter"));
    v.ball_in_hand = f.at("ball_in_hand").name_of<rules::BallInHand>();
    v.group_a = read_groups(f.at("groups"));
    v.choice = read_choice(f.at("choice"));
    v.game_over = f.at("game_over").boolean();
    v.winner = read_optional_player(f.at("winner"));
    v.break_result = f.at("break").name_of<rules::BreakResult>();
    v.state = read_state_impl(f.at("state"), t, Fields::all, v.game_over);
    Field respot = f.at("respot");
    for (std::size_t i = 0; i < respot.array_size(); ++i) {
        const int id = read_ball(respot.at(i), t.game, false);
        if (!v.state.has(id))
            respot.at(i).fail(fmt::format("ball {} is not on the table (state.on_table)", id));
        v.respot.push_back(id);
    }

    if (v.game_over != v.winner.has_value())
        f.at("winner").fail("a winner is named exactly when the game is over");
    if (v.game_over && v.choice) f.at("choice").fail("no choice is offered when the game is over");
    const bool someone_shoots = !v.game_over && !v.choice;
    if (someone_shoots != v.next_shooter.has_value())
        f.at("next_shooter")
            .fail(
                "names the next shooter exactly when no choice is pending and the game is not "
                "over");
    if (v.next_shooter && *v.next_shooter != v.state.shooter)
        f.at("next_shooter").fail("differs from state.shooter");
    if (v.group_a != v.state.group_a) f.at("groups").fail("differs from state.groups");
    return v;
}

physics::Stroke read_stroke(const Field& f) {
    f.require_fields({"speed", "heading_deg", "side", "top", "elevation_deg"});
    physics::Stroke s;
    s.speed = f.at("speed").number_in(0.0, 20.0);
    s.heading_deg = f.at("heading_deg").number_in(-3600.0, 3600.0);
    s.side = f.at("side").number_in(-1.0, 1.0);
    s.top = f.at("top").number_in(-1.0, 1.0);
    s.elevation_deg = f.at("elevation_deg").number_in(0.0, 90.0);
    return s;
}

namespace {

// The fields of an event of `type` beyond time, type, balls, pos, vel and spin.
std::vector<std::string_view> own_fields(physics::EventType type, const Field& f) {
    using physics::EventType;
    switch (type) {
        case EventType::transition:
            return {"from", "to"};
        case EventType::ball_ball:
            return {"speed"};
        case EventType::cushion:
            // One of the two: a cushion, or the jaw of a pocket.
            return {"speed", f.find("pocket_jaw") && !f.find("cushion") ? "pocket_jaw" : "cushion"};
        case EventType::pocket:
            return {"pocket"};
        case EventType::strike:
        case EventType::miscue:
        case EventType::off_table:
            break;
    }
    return {};
}

// `balls`: the event's ball ids, each the cue ball or (when `before` is given) on the table.
void read_event_balls(const Field& balls, physics::Event& e, rules::Game game,
                      const rules::GameState* before) {
    using physics::EventType;
    const std::size_t count = e.type == EventType::ball_ball ? 2 : 1;
    if (balls.array_size() != count)
        balls.fail(fmt::format("a {} event has {} ball{}", physics::to_string(e.type), count,
                               count == 1 ? "" : "s"));
    e.ball_count = static_cast<std::uint8_t>(count);
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t k = 0; k < count; ++k) {
        const int id = read_ball(balls.at(k), game, true);
        if (before && id != 0 && !before->has(id))
            balls.at(k).fail(fmt::format("ball {} is not on the table", id));
        e.balls[k] = {id, {nan, nan}, {}, {}};
    }
    if (count == 2 && e.balls[0].id == e.balls[1].id) balls.fail("two different balls collide");
    if ((e.type == EventType::strike || e.type == EventType::miscue) && e.balls[0].id != 0)
        balls.at(std::size_t{0}).fail("only the cue ball (0) is struck");
}

// `pos`, `vel` and `spin`: one entry per ball of the event.
void read_event_motion(const Field& f, physics::Event& e, Fields fields) {
    const std::size_t count = e.ball_count;
    auto per_ball = [&](std::string_view key, auto read) {
        std::optional<Field> list = fields == Fields::all ? f.at(key) : f.find(key);
        if (!list) return;
        if (list->array_size() != count)
            list->fail(
                fmt::format("expected {} entr{}, one per ball", count, count == 1 ? "y" : "ies"));
        for (std::size_t k = 0; k < count; ++k) read(k, list->at(k));
    };
    per_ball("pos", [&](std::size_t k, const Field& v) { e.balls[k].pos = read_vec2(v); });
    per_ball("vel", [&](std::size_t k, const Field& v) { e.balls[k].vel = read_vec2(v); });
    per_ball("spin", [&](std::size_t k, const Field& v) { e.balls[k].spin = read_vec3(v); });
}

// The fields of the event's type (`own`), and no other.
void read_event_own(const Field& f, physics::Event& e, const std::vector<std::string_view>& own,
                    Fields fields) {
    using physics::EventType;
    auto given = [&](std::string_view key) {
        const bool mine = std::find(own.begin(), own.end(), key) != own.end();
        // A pocket event's pocket is required by the CLI too: the rules need it.
        const bool needed = fields == Fields::all || key == "pocket";
        return mine ? (needed ? std::optional<Field>(f.at(key)) : f.find(key)) : std::nullopt;
    };
    if (auto v = given("from")) e.from = read_motion(*v);
    if (auto v = given("to")) e.to = read_motion(*v);
    if (auto v = given("speed")) e.speed = v->number_in(0.0, 1e6);
    if (auto v = given("cushion")) e.rail = read_rail(*v);
    if (auto v = given("pocket_jaw")) e.pocket = read_pocket(*v);
    if (auto v = given("pocket")) e.pocket = read_pocket(*v);
    for (std::string_view key : {"speed", "cushion", "pocket_jaw", "pocket", "from", "to"}) {
        if (!f.find(key) || std::find(own.begin(), own.end(), key) != own.end()) continue;
        if (e.type == EventType::cushion && (key == "cushion" || key == "pocket_jaw"))
            f.at(key).fail("a cushion event names either a `cushion` or a `pocket_jaw`, not both");
        f.at(key).fail(fmt::format("a {} event has no `{}`", physics::to_string(e.type), key));
    }
}

}  // namespace

physics::Event read_event(const Field& f, rules::Game game, Fields fields,
                          const rules::GameState* before) {
    f.require_fields({"type", "balls"}, {"time", "pos", "vel", "spin", "speed", "cushion",
                                         "pocket_jaw", "pocket", "from", "to"});
    physics::Event e;
    e.type = read_event_type(f.at("type"));
    read_event_balls(f.at("balls"), e, game, before);
    if (std::optional<Field> time = fields == Fields::all ? f.at("time") : f.find("time"))
        e.time = time->number_in(0.0, 1e9);
    read_event_motion(f, e, fields);
    read_event_own(f, e, own_fields(e.type, f), fields);
    return e;
}

}  // namespace game
