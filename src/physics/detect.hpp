// Event prediction: when will a ball next touch another ball, a cushion face, a jaw nose or a
// pocket's drop line, given closed-form motion? Each is the first root of a polynomial of
// degree ≤ 4 in the time from now. Private to physics.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/motion.hpp"
#include "physics/table.hpp"

namespace physics::detect {

/// Balls (or a ball and a cushion) closer than this are touching (unit: m).
inline constexpr double kTouchGap = 1e-10;
/// Normal speeds below this count as zero when deciding whether a touching pair approaches
/// (unit: m/s).
inline constexpr double kApproachEps = 1e-12;

/// A ball's motion from now on, up to a horizon: kinematics now, and how far it can get.
struct Mover {
    motion::Kinematics k;
    double horizon = 0.0;  ///< how far ahead to look (unit: s); may be infinite
    double reach = 0.0;    ///< bound on the distance travelled within the horizon (unit: m)
    bool decelerating = false;  ///< acceleration opposes velocity (rolling): a tighter bound

    /// The same motion looked at only up to `h`.
    Mover within(double h) const;
};

Mover make_mover(const motion::Kinematics& k, double horizon, bool decelerating_along_velocity);

/// Bound on the distance a ball with speed ≤ `speed` and acceleration of size `accel` travels
/// within `horizon` (decelerating: accel opposes the velocity, so it stops).
/// (Inline: the event loop calls it twice per ball pair.)
inline double reach_bound(double speed, double accel, double horizon, bool decelerating) {
    double reach;
    if (std::isinf(horizon)) {
        reach = (speed == 0 && accel == 0) ? 0.0 : std::numeric_limits<double>::infinity();
    } else if (decelerating && accel > 0) {
        const double h = std::min(horizon, speed / accel);  // it stops, then stays
        reach = speed * h - 0.5 * accel * h * h;
    } else {
        reach = speed * horizon + 0.5 * accel * horizon * horizon;
    }
    return std::max(0.0, reach) * (1.0 + 1e-9) + 1e-12;
}

/// A predicted contact: `tau` seconds from now (infinity: none). `pushing`: the contact is now,
/// with no approach speed but an acceleration into it.
struct Prediction {
    double tau = std::numeric_limits<double>::infinity();
    bool pushing = false;
};

Prediction ball_ball(const Mover& a, const Mover& b, double R, double horizon);
Prediction line(const Mover& m, const CushionLine& l, double R);
Prediction nose(const Mover& m, const JawNose& n, double R);
/// Crossing of a pocket's drop line, within `lateral` of the pocket's axis.
double drop(const Mover& m, const Pocket& pk, double lateral);

}  // namespace physics::detect
