// Cue strike after Alciatore, "The Illustrated Principles of Pool and Billiards", technical
// proofs TP A.30 (ball speed and spin from an off-centre hit) and TP A.31 (squirt).
#include "physics/cue_strike.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/portable_math.hpp"

namespace physics {

namespace {
constexpr double kMiscueSpeedFactor = 0.2;  ///< a miscue delivers a weak centre hit
constexpr double kDeg = std::numbers::pi / 180.0;
}  // namespace

StrikeResult strike(const Params& p, const Stroke& st) {
    StrikeResult out;
    double a = st.side, b = st.top;  // tip offsets as fractions of R
    double cue_speed = st.speed;
    if (std::sqrt(a * a + b * b) > p.miscue_limit) {
        out.miscue = true;
        a = b = 0.0;
        cue_speed *= kMiscueSpeedFactor;
    }
    const double m = p.ball_mass, M = p.cue_mass, R = p.ball_radius;
    const double inertia = 0.4 * m * R * R;
    const double phi = st.heading_deg * kDeg, eps = st.elevation_deg * kDeg;
    // Impulse along the cue axis: a collision of the cue (mass M) with the ball's effective
    // mass at the tip's contact point, 1/m_eff = (1 + 5/2·(a² + b²)) / m (TP A.30).
    const double offset2 = a * a + b * b;
    const double impulse = (1.0 + p.cue_tip_e) * cue_speed / (1.0 / M + (1.0 + 2.5 * offset2) / m);
    const Vec3 d{portable::cos(phi) * portable::cos(eps), portable::sin(phi) * portable::cos(eps),
                 -portable::sin(eps)};
    const Vec3 right{portable::sin(phi), -portable::cos(phi), 0.0};
    const Vec3 up = cross(right, d);
    const Vec3 contact = R * (a * right + b * up - std::sqrt(std::max(0.0, 1.0 - offset2)) * d);
    out.spin = (impulse / inertia) * cross(contact, d);
    // The cloth absorbs the downward part of the impulse (no jumps in this engine).
    const double speed = impulse * portable::cos(eps) / m;
    // Squirt (TP A.31): the ball leaves off the stroke line, away from the side of the tip.
    const double squirt = portable::atan(2.5 * a * std::sqrt(1.0 - a * a) /
                                         (1.0 + m / p.cue_endmass + 2.5 * (1.0 - a * a)));
    out.squirt_deg = squirt / kDeg;
    out.vel = {speed * portable::cos(phi + squirt), speed * portable::sin(phi + squirt)};
    return out;
}

double squirt_per_side_offset(const Params& p) {
    return 2.5 / (1.0 + p.ball_mass / p.cue_endmass + 2.5);
}

double cue_speed_for_ball_speed(const Params& p, double ball_speed) {
    return ball_speed * (1.0 + p.ball_mass / p.cue_mass) / (1.0 + p.cue_tip_e);
}

}  // namespace physics
