#include "physics/energy.hpp"

namespace physics {

double kinetic_energy(const Params& p, const BallState& b) {
    if (b.motion == Motion::pocketed) return 0.0;
    const double m = p.ball_mass, R = p.ball_radius;
    const double inertia = 0.4 * m * R * R;
    return 0.5 * m * norm2(b.vel) + 0.5 * inertia * norm2(b.spin);
}

double kinetic_energy(const Params& p, std::span<const BallState> balls) {
    double e = 0.0;
    for (const BallState& b : balls) e += kinetic_energy(p, b);
    return e;
}

}  // namespace physics
