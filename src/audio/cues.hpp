// From a shot's events to sound cues: which sound, when, how loud, at what pitch and where.
// Pure: the same shot and options give the same cues (variants are chosen by a seeded draw).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "audio/sounds.hpp"
#include "physics/shot.hpp"
#include "physics/vec.hpp"

namespace audio {

struct Cue {
    double time = 0.0;  ///< playback time (unit: s from the strike)
    SoundKind kind = SoundKind::ball_click;
    int variant = 0;         ///< which of the bank's variants
    float gain = 1.0f;       ///< linear gain, 0–1 (1: full loudness)
    float pitch = 1.0f;      ///< playback rate, 1 = as synthesized
    physics::Vec3 position;  ///< where it happened, table frame (unit: m)
    double speed = 0.0;      ///< the impact speed it was made from (unit: m/s)
    std::size_t event = 0;   ///< index of its event in the shot
};

struct CueOptions {
    double min_speed = 0.01;           ///< slower impacts are silent (unit: m/s)
    double ball_ball_full = 6.0;       ///< approach speed heard at full loudness (unit: m/s)
    double cushion_full = 4.0;         ///< normal speed into a cushion at full loudness (unit: m/s)
    double strike_full = 8.0;          ///< cue-ball speed off the tip at full loudness (unit: m/s)
    double pocket_full = 3.0;          ///< ball speed into the pocket at full loudness (unit: m/s)
    double loudness_exponent = 1.0;    ///< gain = (speed / full)^exponent: amplitude ∝ speed
    double pitch_per_doubling = 0.04;  ///< pitch rises this fraction per doubling of speed
    double pitch_reference = 1.0;      ///< speed heard at the synthesized pitch (unit: m/s)
    double pitch_jitter = 0.03;        ///< random pitch spread per cue (fraction)
    /// Where a potted ball ends up: the ball return's tray, under the south apron of a 9 ft
    /// table (table frame; unit: m). Its clatter comes return_settle after the drop plus the
    /// run from the pocket at return_speed.
    physics::Vec3 ball_return{1.27, -0.16, -0.20};
    double return_speed = 0.9;  ///< (unit: m/s) along the channel
    double return_settle =
        0.35;  ///< the ball settling in the pocket and finding the channel (unit: s)
    float return_gain = 0.4f;  ///< every run to the return sounds alike, whatever the drop
    int variants = 6;          ///< the bank's variants per kind
    std::uint64_t seed = 1;    ///< for the variant and pitch draws
};

/// Gain for an impact at `speed` heard at full loudness at `full`: (speed/full)^exponent,
/// clamped to [0, 1]. A 0.05 m/s kiss between balls is about −42 dB, a 6 m/s break 0 dB.
float loudness(double speed, double full, double exponent);

/// The cues of a shot, in time order: strike (and miscue), ball–ball, cushion (a jaw gives
/// a rattle), pocket (the drop, and later the ball's run to the return). Transitions are
/// silent; so are impacts slower than min_speed.
std::vector<Cue> cues_for_shot(const physics::Shot& shot, const CueOptions& options = {});

/// Plays a cue list forward in time: due(t) hands out the cues whose time has come since the
/// last call. Going back in time (a replay) starts over from the first cue after t.
class CueSchedule {
  public:
    CueSchedule() = default;
    explicit CueSchedule(std::vector<Cue> cues) : cues_(std::move(cues)) {}

    std::span<const Cue> due(double playback_time);
    const std::vector<Cue>& cues() const { return cues_; }
    bool finished() const { return next_ >= cues_.size(); }

  private:
    std::vector<Cue> cues_;
    std::size_t next_ = 0;
    double last_time_ = -1.0;
};

}  // namespace audio
