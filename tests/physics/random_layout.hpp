// Random layouts and strokes for the property tests (deterministic: our own generator).
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "physics/layout.hpp"
#include "physics/portable_math.hpp"
#include "physics/rack.hpp"
#include "physics/stroke.hpp"
#include "physics/table.hpp"

namespace physics::testing {

struct RandomShot {
    std::vector<BallState> balls;
    Stroke stroke;
    bool is_break = false;
};

/// Every fifth shot is a break of a seeded rack (cue ball anywhere in the kitchen, up to about
/// 12 m/s ball speed); the others are 1–16 balls placed at random with a random stroke.
inline RandomShot random_shot(const Table& t, const Params& p, SplitMix64& rng, int k) {
    RandomShot s;
    const double R = p.ball_radius;
    s.is_break = k % 5 == 0;
    if (s.is_break) {
        s.balls = rack(k % 10 == 0 ? RackType::eight_ball : RackType::nine_ball, t, p, rng.next());
        s.balls[0].pos = {R + rng.uniform() * (t.length() / 4 - 2 * R),
                          R + rng.uniform() * (t.width() - 2 * R)};
        const Vec2 aim = t.foot_spot() - s.balls[0].pos;
        s.stroke.heading_deg =
            portable::atan2(aim.y, aim.x) * 180.0 / std::numbers::pi + (rng.uniform() - 0.5) * 10.0;
        s.stroke.speed = 3.0 + 6.0 * rng.uniform();  // cue speed; ball speed up to ~12 m/s
    } else {
        const int n = 1 + static_cast<int>(rng.below(16));
        for (int id = 0; id < n; ++id) {
            for (int tries = 0; tries < 100; ++tries) {
                BallState b;
                b.id = id;
                b.pos = {R + rng.uniform() * (t.length() - 2 * R),
                         R + rng.uniform() * (t.width() - 2 * R)};
                s.balls.push_back(b);
                if (!validate_layout(t, p, s.balls)) break;
                s.balls.pop_back();
            }
        }
        s.stroke.heading_deg = 360.0 * rng.uniform();
        s.stroke.speed = 0.1 + 7.0 * rng.uniform();
    }
    s.stroke.side = (rng.uniform() - 0.5) * 1.1;
    s.stroke.top = (rng.uniform() - 0.5) * 1.1;
    s.stroke.elevation_deg = rng.uniform() < 0.8 ? 0.0 : 30.0 * rng.uniform();
    return s;
}

}  // namespace physics::testing
