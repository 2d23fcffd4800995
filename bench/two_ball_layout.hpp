// The benchmarks' random two-ball layouts (ai_strength shots, shot_calibration): the cue ball and
// the 9 anywhere on the table, at least 2.5 R apart.
#pragma once

#include <map>

#include "physics/rack.hpp"
#include "physics/table.hpp"
#include "physics/vec.hpp"

namespace bench {

/// The cue ball (id 0) and the 9, drawn uniformly over the bed (four draws a try).
inline std::map<int, physics::Vec2> two_ball_layout(const physics::Table& table, double R,
                                                    physics::SplitMix64& rng) {
    const double L = table.length(), W = table.width();
    physics::Vec2 cue, obj;
    do {
        cue = {R + rng.uniform() * (L - 2 * R), R + rng.uniform() * (W - 2 * R)};
        obj = {R + rng.uniform() * (L - 2 * R), R + rng.uniform() * (W - 2 * R)};
    } while (physics::norm(cue - obj) < 2.5 * R);
    return {{0, cue}, {9, obj}};
}

}  // namespace bench
