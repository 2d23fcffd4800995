#include "audio/cues.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "audio/rng.hpp"

namespace audio {
namespace {

using physics::EventType;

struct Impact {
    SoundKind kind;
    double speed;  ///< (unit: m/s)
    double full;   ///< speed at full loudness (unit: m/s)
};

/// The ball's speed just before time t (its state at t is the one after the event).
double speed_before(const physics::Shot& shot, int ball, double t) {
    const double before = std::nextafter(t, -1.0);
    return physics::norm(shot.state_at(ball, std::max(0.0, before)).vel);
}

bool impact_of(const physics::Shot& shot, const physics::Event& e, const CueOptions& o,
               Impact& out) {
    switch (e.type) {
        case EventType::strike:
        case EventType::miscue:
            out = {SoundKind::cue_strike, physics::norm(e.balls[0].vel), o.strike_full};
            return true;
        case EventType::ball_ball:
            out = {SoundKind::ball_click, e.speed, o.ball_ball_full};
            return true;
        case EventType::cushion:
            out = {e.pocket >= 0 ? SoundKind::jaw_rattle : SoundKind::cushion_thump, e.speed,
                   o.cushion_full};
            return true;
        case EventType::pocket:
            out = {SoundKind::pocket_drop, speed_before(shot, e.ball(0), e.time), o.pocket_full};
            return true;
        case EventType::transition:
        case EventType::off_table:
            return false;
    }
    return false;
}

physics::Vec3 where(const physics::Event& e, double ball_radius) {
    physics::Vec2 p = e.balls[0].pos;
    if (e.type == EventType::ball_ball) p = 0.5 * (e.balls[0].pos + e.balls[1].pos);
    return physics::lift(p, ball_radius);
}

/// A different variant from this kind's previous one, so two sounds in a row differ.
int next_variant(std::array<int, kSoundKindCount>& last_variant, SoundKind kind, int variants,
                 Rng& rng) {
    int& last = last_variant[static_cast<std::size_t>(kind)];
    const int n = std::max(1, variants);
    last = (last < 0 || n == 1) ? rng.below(n) : (last + 1 + rng.below(n - 1)) % n;
    return last;
}

/// The potted ball's run from the pocket to the ball return, heard after its drop.
Cue return_cue(const Cue& drop, const CueOptions& o, std::array<int, kSoundKindCount>& last,
               Rng& rng) {
    Cue c = drop;
    const physics::Vec3 d = o.ball_return - drop.position;
    c.time = drop.time + o.return_settle + std::hypot(d.x, d.y) / o.return_speed;
    c.kind = SoundKind::ball_return;
    c.variant = next_variant(last, c.kind, o.variants, rng);
    c.gain = o.return_gain;
    c.pitch = static_cast<float>(rng.jitter(o.pitch_jitter));
    c.position = o.ball_return;
    return c;
}

}  // namespace

float loudness(double speed, double full, double exponent) {
    if (!(speed > 0.0) || !(full > 0.0)) return 0.0f;
    return static_cast<float>(std::clamp(std::pow(speed / full, exponent), 0.0, 1.0));
}

std::vector<Cue> cues_for_shot(const physics::Shot& shot, const CueOptions& o) {
    std::vector<Cue> cues;
    std::array<int, kSoundKindCount> last_variant;
    last_variant.fill(-1);
    const auto& events = shot.events();
    for (std::size_t i = 0; i < events.size(); ++i) {
        const physics::Event& e = events[i];
        Impact impact{};
        if (!impact_of(shot, e, o, impact) || impact.speed < o.min_speed) continue;
        Rng rng(mix_seed(o.seed, i));
        Cue c;
        c.time = e.time;
        c.kind = impact.kind;
        c.variant = next_variant(last_variant, impact.kind, o.variants, rng);
        c.gain = loudness(impact.speed, impact.full, o.loudness_exponent);
        const double doublings = std::log2(std::max(impact.speed, 1e-3) / o.pitch_reference);
        const double pitch = (1.0 + o.pitch_per_doubling * doublings) * rng.jitter(o.pitch_jitter);
        c.pitch = static_cast<float>(std::clamp(pitch, 0.8, 1.25));
        c.position = where(e, shot.params().ball_radius);
        c.speed = impact.speed;
        c.event = i;
        cues.push_back(c);
        if (c.kind == SoundKind::pocket_drop) cues.push_back(return_cue(c, o, last_variant, rng));
    }
    std::stable_sort(cues.begin(), cues.end(),
                     [](const Cue& a, const Cue& b) { return a.time < b.time; });
    return cues;
}

std::span<const Cue> CueSchedule::due(double t) {
    if (t < last_time_) {
        next_ = static_cast<std::size_t>(
            std::upper_bound(cues_.begin(), cues_.end(), t,
                             [](double time, const Cue& c) { return time < c.time; }) -
            cues_.begin());
        // Cues exactly at t count as already played when rewinding to t.
    }
    last_time_ = t;
    const std::size_t first = next_;
    while (next_ < cues_.size() && cues_[next_].time <= t) ++next_;
    return {cues_.data() + first, next_ - first};
}

}  // namespace audio
