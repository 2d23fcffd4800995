#include "game/practice.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "game/json_field.hpp"
#include "game/session.hpp"
#include "game/state_json.hpp"
#include "physics/layout.hpp"
#include "physics/rack.hpp"
#include "physics/simulate.hpp"

namespace game {

namespace {

std::string ball_words(int id) {
    return id == 0 ? "The cue ball" : fmt::format("The {}", id);
}

physics::Table checked_table(const physics::TableSpec& spec, double ball_radius) {
    if (std::optional<std::string> e = physics::validate_table_spec(spec, ball_radius))
        throw std::invalid_argument("game::Practice: table: " + *e);
    if (!spec.bounded) throw std::invalid_argument("game::Practice: table: must have cushions");
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

Practice::Practice(physics::TableSpec table, physics::Params params)
    : spec_(std::move(table)),
      params_(std::move(params)),
      table_(checked_table(spec_, params_.ball_radius)) {}

Practice::Practice(rules::Game game, physics::TableSpec table, physics::Params params,
                   std::uint64_t seed)
    : Practice(std::move(table), std::move(params)) {
    game_ = game;
    const physics::RackType type = game == rules::Game::eight_ball ? physics::RackType::eight_ball
                                                                   : physics::RackType::nine_ball;
    for (const physics::BallState& b : physics::rack(type, table_, params_, seed))
        if (b.id != 0) balls_[b.id] = b.pos;
    balls_[0] = free_spot_near_head();
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
    if (!balls_.count(id)) return fmt::format("The {} is not on the table.", id);
    return check_place(id, pos);
}

std::optional<std::string> Practice::check_place(int id, physics::Vec2 pos) const {
    if (!std::isfinite(pos.x) || !std::isfinite(pos.y) ||
        !table_.on_surface(pos, params_.ball_radius))
        return ball_words(id) + " must go on the cloth.";
    for (const auto& [other, p] : balls_)
        if (other != id &&
            physics::norm(p - pos) < 2.0 * params_.ball_radius - physics::overlap_tolerance)
            return fmt::format("{} can't go on top of the {}.", ball_words(id),
                               other == 0 ? std::string("cue ball") : std::to_string(other));
    return std::nullopt;
}

bool Practice::move(int id, physics::Vec2 pos) {
    if (check_move(id, pos)) return false;
    balls_[id] = pos;
    return true;
}

// The head spot, else the nearest free place on a grid of half-radius steps around it.
physics::Vec2 Practice::free_spot_near_head() const {
    const double step = params_.ball_radius / 2.0;
    const physics::Vec2 head = table_.head_spot();
    for (int ring = 0; ring < 400; ++ring)
        for (int i = -ring; i <= ring; ++i)
            for (int j = -ring; j <= ring; ++j) {
                if (std::max(std::abs(i), std::abs(j)) != ring) continue;
                const physics::Vec2 p{head.x + i * step, head.y + j * step};
                bool free = table_.on_surface(p, params_.ball_radius);
                for (const auto& [id, q] : balls_)
                    if (id != 0 && physics::norm(q - p) < 2.0 * params_.ball_radius) free = false;
                if (free) return p;
            }
    throw std::logic_error("game::Practice: no free place for the cue ball");
}

const physics::Shot& Practice::play(const physics::Stroke& stroke) {
    check_stroke(stroke);
    if (!balls_.count(0)) throw std::logic_error("game::Practice: no cue ball");
    last_shot_ = physics::simulate(table_, params_, ball_states(), &stroke);
    before_.push_back(balls_);
    balls_.clear();
    for (const physics::BallState& b : last_shot_->final_states())
        if (b.motion != physics::Motion::pocketed) balls_[b.id] = b.pos;
    if (!balls_.count(0)) balls_[0] = free_spot_near_head();
    return *last_shot_;
}

void Practice::try_again() {
    if (before_.empty()) return;
    balls_ = std::move(before_.back());
    before_.pop_back();
}

}  // namespace game
