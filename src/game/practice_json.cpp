// A practice position as the `simulate` input of docs/cli.md: Practice::to_json and
// Practice::from_json.
#include <fmt/format.h>

#include <algorithm>

#include "game/json_field.hpp"
#include "game/practice.hpp"
#include "game/state_json.hpp"
#include "physics/layout.hpp"
#include "physics/markings.hpp"

namespace game {

namespace {

constexpr int max_pool_ball = 15;           ///< the 8-ball and 9-ball tables' balls
constexpr double min_snooker_length = 3.0;  ///< (unit: m) longer than any pool table (9 ft: 2.54)

// A ball of the position: {"id", "pos"}, and a velocity or spin only if zero (balls at rest).
std::pair<int, physics::Vec2> read_ball(const Field& f) {
    f.expect_object({"id", "pos", "vel", "spin"});
    const int id = static_cast<int>(f.at("id").integer_in(0, physics::max_ball_id));
    const physics::Vec2 pos = read_vec2(f.at("pos"));
    if (std::optional<Field> v = f.find("vel"); v && physics::norm(read_vec2(*v)) != 0.0)
        v->fail("a position's balls are at rest: the velocity must be [0, 0] or left out");
    if (std::optional<Field> w = f.find("spin")) {
        const physics::Vec3 s = read_vec3(*w);
        if (s.x != 0.0 || s.y != 0.0 || s.z != 0.0)
            w->fail("a position's balls are at rest: the spin must be [0, 0, 0] or left out");
    }
    return {id, pos};
}

// Whose table and balls a position's are: no pockets, three-cushion; a snooker colour or a
// table longer than any pool table, snooker; else 8-ball with a ball above the 9, else 9-ball.
physics::RackType game_of(const physics::TableSpec& spec, const std::vector<int>& ids) {
    if (!spec.pockets) return physics::RackType::three_cushion;
    const int top = ids.empty() ? 0 : *std::max_element(ids.begin(), ids.end());
    if (top > max_pool_ball || spec.length > min_snooker_length) return physics::RackType::snooker;
    return top > 9 ? physics::RackType::eight_ball : physics::RackType::nine_ball;
}

// Why ball `id` is not one of `game`'s balls, or empty.
std::optional<std::string> foreign_ball(physics::RackType game, int id) {
    if (game == physics::RackType::three_cushion && id > physics::carom_ball::red)
        return fmt::format(
            "a table without pockets holds the three-cushion balls: 0 (white), 1 (yellow), 2 "
            "(red); there is no ball {}",
            id);
    return std::nullopt;
}

}  // namespace

std::string Practice::to_json() const {
    nlohmann::ordered_json balls = nlohmann::ordered_json::array();
    for (const auto& [id, pos] : balls_) balls.push_back({{"id", id}, {"pos", game::to_json(pos)}});
    const nlohmann::ordered_json j{{"table", game::to_json(spec_)},
                                   {"params", game::to_json(params_)},
                                   {"balls", std::move(balls)}};
    return j.dump(2) + "\n";
}

Practice Practice::from_json(std::string_view text) {
    const nlohmann::json doc = parse_document(text, "position");
    const Field root(doc, "position");
    root.expect_object({"table", "params", "balls", "strike"});
    const physics::Params params =
        root.find("params") ? read_params(root.at("params"), Fields::required) : physics::Params{};
    const physics::TableSpec spec =
        root.find("table") ? read_table(root.at("table"), params.ball_radius, Fields::required)
                           : physics::TableSpec{};
    if (!spec.bounded) root.at("table").fail("practice needs a table with cushions");
    const Field balls = root.at("balls");
    std::vector<std::pair<int, physics::Vec2>> read;
    std::vector<int> ids;
    for (std::size_t i = 0; i < balls.array_size(); ++i) {
        read.push_back(read_ball(balls.at(i)));
        ids.push_back(read.back().first);
    }
    Practice p(game_of(spec, ids), spec, params);
    for (std::size_t i = 0; i < read.size(); ++i) {
        const auto [id, pos] = read[i];
        if (std::optional<std::string> why = foreign_ball(p.game_, id))
            balls.at(i).at("id").fail(*why);
        if (p.balls_.count(id))
            balls.at(i).at("id").fail(fmt::format("ball {} is listed twice", id));
        if (std::optional<std::string> why = p.check_place(id, pos))
            balls.at(i).at("pos").fail(*why);
        p.balls_[id] = pos;
    }
    if (!p.balls_.count(0)) balls.fail("the cue ball (id 0) is missing");
    return p;
}

}  // namespace game
