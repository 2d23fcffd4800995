// A practice position as the `simulate` input of docs/cli.md: Practice::to_json and
// Practice::from_json.
#include <fmt/format.h>

#include "game/json_field.hpp"
#include "game/practice.hpp"
#include "game/state_json.hpp"
#include "physics/layout.hpp"

namespace game {

namespace {

constexpr std::int64_t max_pool_ball = 15;  ///< the 8-ball and 9-ball tables' balls

// A ball of the position: {"id", "pos"}, and a velocity or spin only if zero (balls at rest).
std::pair<int, physics::Vec2> read_ball(const Field& f) {
    f.expect_object({"id", "pos", "vel", "spin"});
    const int id = static_cast<int>(f.at("id").integer_in(0, max_pool_ball));
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
    Practice p(spec, params);
    const Field balls = root.at("balls");
    for (std::size_t i = 0; i < balls.array_size(); ++i) {
        const auto [id, pos] = read_ball(balls.at(i));
        if (p.balls_.count(id))
            balls.at(i).at("id").fail(fmt::format("ball {} is listed twice", id));
        if (std::optional<std::string> why = p.check_place(id, pos))
            balls.at(i).at("pos").fail(*why);
        p.balls_[id] = pos;
    }
    if (!p.balls_.count(0)) balls.fail("the cue ball (id 0) is missing");
    p.game_ = p.balls_.rbegin()->first > 9 ? rules::Game::eight_ball : rules::Game::nine_ball;
    return p;
}

}  // namespace game
