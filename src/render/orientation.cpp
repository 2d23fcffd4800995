#include "render/orientation.hpp"

#include <algorithm>
#include <cmath>

namespace render {

glm::dquat advance(const glm::dquat& q, physics::Vec3 omega, double dt) {
    const double w = physics::norm(omega);
    const double angle = w * dt;
    if (!(angle > 1e-15)) return q;
    const glm::dvec3 axis{omega.x / w, omega.y / w, omega.z / w};
    return glm::normalize(glm::angleAxis(angle, axis) * q);
}

glm::dquat integrate_orientation(const physics::Shot& shot, int id, double t0, double t1,
                                 const glm::dquat& q0, double max_step) {
    if (!(t1 > t0) || !shot.index_of(id)) return q0;
    const int steps = std::max(1, static_cast<int>(std::ceil((t1 - t0) / max_step)));
    const double h = (t1 - t0) / steps;
    glm::dquat q = q0;
    for (int i = 0; i < steps; ++i) {
        const physics::BallState s = shot.state_at(id, t0 + (i + 0.5) * h);
        if (s.motion == physics::Motion::pocketed) break;
        q = advance(q, s.spin, h);
    }
    return q;
}

glm::dquat initial_orientation(int id) {
    // Golden-angle spread of axes and angles: deterministic and varied.
    const double a = 2.399963229728653 * (id + 1);
    const double z = std::cos(1.7 * id + 0.3);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const glm::dvec3 axis{r * std::cos(a), r * std::sin(a), z};
    return glm::angleAxis(0.6 + 0.9 * id, glm::normalize(axis));
}

}  // namespace render
