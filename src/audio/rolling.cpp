#include "audio/rolling.hpp"

#include <algorithm>

#include "audio/cues.hpp"

namespace audio {

std::vector<Roll> rolling_at(const physics::Shot& shot, double t, const RollOptions& o) {
    std::vector<Roll> out(shot.ball_count());
    const double R = shot.params().ball_radius;
    for (std::size_t i = 0; i < shot.ball_count(); ++i) {
        Roll& r = out[i];
        r.ball = shot.ball_id(i);
        const physics::BallState b = shot.state_at(r.ball, std::max(0.0, t));
        r.position = physics::lift(b.pos, R);
        const bool on_cloth =
            b.motion == physics::Motion::rolling || b.motion == physics::Motion::sliding;
        const double speed = physics::norm(b.vel);
        if (!o.enabled || t < 0.0 || !on_cloth || speed < o.min_speed) continue;
        const double scrub = b.motion == physics::Motion::sliding ? o.sliding : 1.0;
        r.gain = std::min(1.0f, loudness(speed, o.full, 1.0) * static_cast<float>(scrub));
        r.pitch = static_cast<float>(std::min(1.3, o.pitch_low + o.pitch_per_mps * speed));
    }
    return out;
}

}  // namespace audio
