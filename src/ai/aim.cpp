#include "ai/internal/aim.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>

#include "game/stroke_noise.hpp"
#include "physics/simulate.hpp"

namespace ai {

namespace {

// The direction error of ball `watched` just after it is first struck (unit: rad; + is
// counter-clockwise of `wanted`); empty when a cushion comes first or it is never struck.
template <std::size_t N>
std::optional<double> direction_error(const physics::Table& table, const physics::Params& params,
                                      const std::array<physics::BallState, N>& balls, int watched,
                                      physics::Vec2 wanted, const physics::Stroke& stroke,
                                      int max_events) {
    physics::SimOptions options;
    options.max_events = max_events;  // the contact comes within the first few events
    const physics::Shot shot = physics::simulate(table, params, balls, &stroke, options);
    for (const physics::Event& e : shot.events()) {
        if (e.type == physics::EventType::cushion) return std::nullopt;
        if (e.type != physics::EventType::ball_ball) continue;
        if (e.balls[0].id != watched && e.balls[1].id != watched) continue;
        const physics::EventBall& b = e.balls[0].id == watched ? e.balls[0] : e.balls[1];
        const physics::Vec2 v = b.vel;
        if (physics::norm2(v) == 0.0) return std::nullopt;
        return std::atan2(physics::cross(wanted, v), physics::dot(wanted, v));
    }
    return std::nullopt;
}

// The secant method on the heading: `error(h)` is the watched ball's direction error for the
// heading h, and turning the stroke by dh turns that ball by about −gain·dh.
template <typename Error>
double secant_heading(double start_deg, double gain, int iterations, std::int64_t& simulations,
                      Error error) {
    double h0 = start_deg;
    ++simulations;
    std::optional<double> e0 = error(h0);
    if (!e0) return start_deg;
    double h1 = h0 + *e0 / gain / deg;
    for (int k = 0; k < iterations; ++k) {
        ++simulations;
        std::optional<double> e1 = error(h1);
        if (!e1) return h0;
        if (std::fabs(*e1) < 1e-6 || *e1 == *e0) return h1;
        const double h2 = h1 - *e1 * (h1 - h0) / (*e1 - *e0);
        h0 = h1;
        e0 = e1;
        // Never wander far from the ghost-ball heading: the shot model would not hold.
        h1 = std::clamp(h2, start_deg - 3.0, start_deg + 3.0);
    }
    return h1;
}

}  // namespace

double refine_heading(const physics::Table& table, const physics::Params& params, physics::Vec2 cue,
                      physics::Vec2 object, const Aim& aim, physics::Stroke stroke, int iterations,
                      std::int64_t& simulations) {
    const double R = params.ball_radius;
    const double cos_cut = std::max(std::cos(aim.cut_deg * deg), 0.05);
    const double gain = aim.cue_distance / (2.0 * R * cos_cut);
    std::array<physics::BallState, 2> balls{};
    balls[0].pos = cue;
    balls[1].id = aim.ball;
    balls[1].pos = object;
    return secant_heading(aim.heading_deg, gain, iterations, simulations, [&](double h) {
        stroke.heading_deg = h;
        return direction_error(table, params, balls, aim.ball, aim.object_dir, stroke, 10);
    });
}

namespace {

// Which ball a stroke watches and the direction it leaves in (unit: rad).
struct Struck {
    int ball = 0;
    double direction = 0.0;
};

// The elevation (0 to `max_deg`) of `stroke`'s cue at which a side error of −σ and one of +σ
// send the ball that `strike(stroke)` reports off in the same direction, by the secant method;
// 0 where raising the cue does not lessen the turn. Adds two simulations per elevation tried.
template <typename Strike>
double cancelling_elevation(physics::Stroke stroke, double max_deg, std::int64_t& simulations,
                            Strike strike) {
    const double side_step = game::StrokeNoise{}.offset;  // one σ of the tip offset (unit: R)
    constexpr double first_try = 12.0;                    // (unit: deg)
    const double side = stroke.side;
    // How much the ball's direction turns from a side error of −step to +step.
    const auto sensitivity = [&](double elevation) -> std::optional<double> {
        stroke.elevation_deg = elevation;
        simulations += 2;
        stroke.side = side + side_step;
        const std::optional<Struck> plus = strike(stroke);
        stroke.side = side - side_step;
        const std::optional<Struck> minus = strike(stroke);
        if (!plus || !minus || plus->ball != minus->ball) return std::nullopt;
        return std::remainder(plus->direction - minus->direction, 2.0 * std::numbers::pi);
    };
    double e0 = 0.0, e1 = std::min(first_try, max_deg);
    std::optional<double> s0 = sensitivity(e0), s1 = sensitivity(e1);
    if (!s0 || !s1 || std::fabs(*s1) >= std::fabs(*s0)) return 0.0;
    for (int k = 0; k < 2; ++k) {
        if (*s1 == *s0) break;
        const double e2 = std::clamp(e1 - *s1 * (e1 - e0) / (*s1 - *s0), 0.0, max_deg);
        if (std::fabs(e2 - e1) < 0.25) return e2;
        const std::optional<double> s2 = sensitivity(e2);
        if (!s2) break;
        e0 = e1;
        s0 = s1;
        e1 = e2;
        s1 = s2;
    }
    return e1;
}

// The first object ball the cue ball strikes, after any cushions, and the direction it leaves
// in; empty when the cue ball strikes none within `max_events`.
std::optional<Struck> first_struck(const physics::Table& table, const physics::Params& params,
                                   std::span<const physics::BallState> balls,
                                   const physics::Stroke& stroke, int max_events) {
    physics::SimOptions options;
    options.max_events = max_events;
    const physics::Shot shot = physics::simulate(table, params, balls, &stroke, options);
    for (const physics::Event& e : shot.events()) {
        if (e.type != physics::EventType::ball_ball) continue;
        if (e.balls[0].id != 0 && e.balls[1].id != 0) return std::nullopt;  // not the cue ball
        const physics::EventBall& b = e.balls[0].id == 0 ? e.balls[1] : e.balls[0];
        if (physics::norm2(b.vel) == 0.0) return std::nullopt;
        return Struck{b.id, std::atan2(b.vel.y, b.vel.x)};
    }
    return std::nullopt;
}

}  // namespace

double compensating_elevation(const physics::Table& table, const physics::Params& params,
                              physics::Vec2 cue, physics::Vec2 object, const Aim& aim,
                              physics::Stroke stroke, double max_deg, std::int64_t& simulations) {
    std::array<physics::BallState, 2> balls{};
    balls[0].pos = cue;
    balls[1].id = aim.ball;
    balls[1].pos = object;
    return cancelling_elevation(
        stroke, max_deg, simulations, [&](const physics::Stroke& s) -> std::optional<Struck> {
            const std::optional<double> error =
                direction_error(table, params, balls, aim.ball, aim.object_dir, s, 10);
            if (!error) return std::nullopt;
            return Struck{aim.ball, *error};
        });
}

double kick_compensating_elevation(const physics::Table& table, const physics::Params& params,
                                   std::span<const physics::BallState> balls,
                                   physics::Stroke stroke, double max_deg,
                                   std::int64_t& simulations) {
    constexpr int max_events = 40;  // the first contact comes within a few cushions
    return cancelling_elevation(stroke, max_deg, simulations, [&](const physics::Stroke& s) {
        return first_struck(table, params, balls, s, max_events);
    });
}

double speed_for_elevation(const physics::Stroke& stroke, double elevation_deg) {
    const double ball_speed = stroke.speed * std::cos(stroke.elevation_deg * deg);
    return ball_speed / std::cos(elevation_deg * deg);
}

physics::Stroke raised_stroke(const physics::Table& table, const physics::Params& params,
                              physics::Vec2 cue, physics::Vec2 object, const Aim& aim,
                              physics::Stroke stroke, double elevation_deg, double min_speed,
                              double max_speed, int refine_steps, std::int64_t& simulations) {
    stroke.speed = std::clamp(speed_for_elevation(stroke, elevation_deg), min_speed, max_speed);
    stroke.elevation_deg = elevation_deg;
    stroke.heading_deg =
        refine_heading(table, params, cue, object, aim, stroke, refine_steps, simulations);
    return stroke;
}

double refine_combination_heading(const physics::Table& table, const physics::Params& params,
                                  physics::Vec2 cue, const std::map<int, physics::Vec2>& balls,
                                  const Combination& c, physics::Stroke stroke, int iterations,
                                  std::int64_t& simulations) {
    const double R = params.ball_radius;
    const double cos_first = std::max(std::cos(c.first.cut_deg * deg), 0.05);
    const double cos_second = std::max(std::cos(c.second.cut_deg * deg), 0.05);
    const double gain = c.first.cue_distance / (2.0 * R * cos_first) *
                        (c.first.object_distance / (2.0 * R * cos_second) + 1.0);
    std::array<physics::BallState, 3> three{};
    three[0].pos = cue;
    three[1].id = c.first.ball;
    three[1].pos = balls.at(c.first.ball);
    three[2].id = c.second.ball;
    three[2].pos = balls.at(c.second.ball);
    return secant_heading(c.first.heading_deg, gain, iterations, simulations, [&](double h) {
        stroke.heading_deg = h;
        return direction_error(table, params, three, c.second.ball, c.second.object_dir, stroke,
                               20);
    });
}

}  // namespace ai
