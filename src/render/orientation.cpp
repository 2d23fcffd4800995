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
    // The number circles' axis (ball x) tilted 35–75° up from the cloth, at golden-angle
    // azimuths, with a varied roll about it: deterministic and varied, stripes and numbers
    // not all facing up, yet most numbers readable from above as on a freshly racked table.
    const double golden = 2.399963229728653;
    const double azimuth = golden * (id + 1);
    const double elevation = 0.61 + 0.70 * (0.5 + 0.5 * std::sin(1.7 * id + 0.3));
    const double roll = 0.6 + 0.9 * id;
    return glm::angleAxis(azimuth, glm::dvec3(0, 0, 1)) *
           glm::angleAxis(-elevation, glm::dvec3(0, 1, 0)) *
           glm::angleAxis(roll, glm::dvec3(1, 0, 0));
}

}  // namespace render
