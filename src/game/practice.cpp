#include "game/practice.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "game/carom_session.hpp"
#include "game/json_field.hpp"
#include "game/session.hpp"
#include "game/snooker_session.hpp"
#include "game/state_json.hpp"
#include "physics/layout.hpp"
#include "physics/markings.hpp"
#include "physics/rack.hpp"
#include "physics/simulate.hpp"

namespace game {

namespace {

physics::Table checked_table(physics::RackType game, const physics::TableSpec& spec,
                             double ball_radius) {
    if (std::optional<std::string> e = physics::validate_table_spec(spec, ball_radius))
        throw std::invalid_argument("game::Practice: table: " + *e);
    if (!spec.bounded) throw std::invalid_argument("game::Practice: table: must have cushions");
    if ((game == physics::RackType::three_cushion) == spec.pockets)
        throw std::invalid_argument(
            "game::Practice: table: three-cushion is played on a table without pockets, the "
            "other games on one with pockets");
    return physics::build_table(spec);
}

void check_stroke(const physics::Stroke& s) {
    const bool finite = std::isfinite(s.speed) && std::isfinite(s.heading_deg) &&
                        std::isfinite(s.side) && std::isfinite(s.top) &&
                        std::isfinite(s.elevation_deg);
    if (!finite || s.speed < 0.0 || s.speed > max_stroke_speed || std::fabs(s.side) > 1.0 ||
        std::fabs(s.top) > 1.0 || s.elevation_deg < 0.0 || s.elevation_deg > 90.0)
        throw std::invalid_argument(
            fmt::format("game::Practice: the stroke must have finite numbers, a speed from 0 to "
                        "{} m/s, tip offsets from -1 to 1 and an elevation from 0 to 90 degrees",
                        max_stroke_speed));
}

}  // namespace

// The homes are the starting position's places: the cue ball's (the head spot, snooker's spot
// in the D, the white's starting spot) and, on a table without pockets, every ball's.
Practice::Practice(physics::RackType game, physics::TableSpec table, physics::Params params)
    : game_(game),
      spec_(std::move(table)),
      params_(std::move(params)),
      table_(checked_table(game_, spec_, params_.ball_radius)) {
    for (const physics::BallState& b : physics::rack(game_, table_, params_, 0))
        if (b.id == 0 || !spec_.pockets) home_[b.id] = b.pos;
}

Practice::Practice(physics::RackType game, physics::TableSpec table, physics::Params params,
                   std::uint64_t seed)
    : Practice(game, std::move(table), std::move(params)) {
    for (const physics::BallState& b : physics::rack(game_, table_, params_, seed))
        if (b.id != 0) balls_[b.id] = b.pos;
    balls_[0] = free_spot_near_home(0);
}

Practice Practice::on_own_table(physics::RackType game, std::uint64_t seed) {
    switch (game) {
        case physics::RackType::snooker:
            return Practice(game, physics::snooker_table_spec(), *physics::params_preset("snooker"),
                            seed);
        case physics::RackType::three_cushion:
            return Practice(game, physics::carom_table_spec(), *physics::params_preset("carom"),
                            seed);
        default:
            return Practice(game, physics::TableSpec{}, physics::Params{}, seed);
    }
}

std::string Practice::ball_name(int id) const {
    if (game_ == physics::RackType::three_cushion) return carom_ball_name(id);
    if (id == 0) return "cue ball";
    if (game_ == physics::RackType::snooker) return snooker_ball_name(id);
    return std::to_string(id);
}

std::string Practice::return_words() const {
    switch (game_) {
        case physics::RackType::snooker:
            return "in the D";
        case physics::RackType::three_cushion:
            return "on its starting spot";
        default:
            return "on the head spot";
    }
}

std::vector<physics::BallState> Practice::ball_states() const {
    std::vector<physics::BallState> out;
    for (const auto& [id, pos] : balls_) {
        physics::BallState b;
        b.id = id;
        b.pos = pos;
        out.push_back(b);
    }
    return out;
}

std::optional<std::string> Practice::check_move(int id, physics::Vec2 pos) const {
    if (!balls_.count(id)) return fmt::format("The {} is not on the table.", ball_name(id));
    return check_place(id, pos);
}

std::optional<std::string> Practice::check_place(int id, physics::Vec2 pos) const {
    if (!std::isfinite(pos.x) || !std::isfinite(pos.y) ||
        !table_.on_surface(pos, params_.ball_radius))
        return fmt::format("The {} must go on the cloth.", ball_name(id));
    for (const auto& [other, p] : balls_)
        if (other != id &&
            physics::norm(p - pos) < 2.0 * params_.ball_radius - physics::overlap_tolerance)
            return fmt::format("The {} can't go on top of the {}.", ball_name(id),
                               ball_name(other));
    return std::nullopt;
}

bool Practice::move(int id, physics::Vec2 pos) {
    if (check_move(id, pos)) return false;
    balls_[id] = pos;
    return true;
}

bool Practice::may_lie_at(int id, physics::Vec2 p) const {
    if (!table_.on_surface(p, params_.ball_radius)) return false;
    if (game_ == physics::RackType::snooker && id == 0 &&
        !physics::snooker_markings(table_).in_d(p))
        return false;  // the cue ball comes back in the D, as after an in-off
    for (const auto& [other, q] : balls_)
        if (other != id && physics::norm(q - p) < 2.0 * params_.ball_radius) return false;
    return true;
}

// The home, else the nearest free place on a grid of half-radius steps around it.
physics::Vec2 Practice::free_spot_near_home(int id) const {
    const double step = params_.ball_radius / 2.0;
    const physics::Vec2 home = home_.at(id);
    for (int ring = 0; ring < 400; ++ring)
        for (int i = -ring; i <= ring; ++i)
            for (int j = -ring; j <= ring; ++j) {
                if (std::max(std::abs(i), std::abs(j)) != ring) continue;
                const physics::Vec2 p{home.x + i * step, home.y + j * step};
                if (may_lie_at(id, p)) return p;
            }
    throw std::logic_error("game::Practice: no free place for the " + ball_name(id));
}

const physics::Shot& Practice::play(const physics::Stroke& stroke) {
    check_stroke(stroke);
    if (!balls_.count(0)) throw std::logic_error("game::Practice: no cue ball");
    last_shot_ = physics::simulate(table_, params_, ball_states(), &stroke);
    before_.push_back(balls_);
    balls_.clear();
    for (const physics::BallState& b : last_shot_->final_states())
        if (b.motion != physics::Motion::pocketed) balls_[b.id] = b.pos;
    // Nothing can drop on a table without pockets, but every ball there has a home all the same.
    for (const auto& [id, home] : home_)
        if (before_.back().count(id) && !balls_.count(id)) balls_[id] = free_spot_near_home(id);
    return *last_shot_;
}

void Practice::try_again() {
    if (before_.empty()) return;
    balls_ = std::move(before_.back());
    before_.pop_back();
}

}  // namespace game
