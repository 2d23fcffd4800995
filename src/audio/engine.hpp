// The sound of a shot during playback, through OpenAL Soft: the thin edge of the module (only
// engine.cpp includes OpenAL). Without an audio device the engine runs silent: one line on
// stderr when it opens, and every call is then a no-op.
//
//   audio::Engine sound;                      // opens the default device (or runs silent)
//   sound.set_muted(!settings.sound);         // the app persists the setting
//   sound.start(shot);                        // a new shot: playback time 0 is the strike
//   each frame: sound.set_listener(camera); sound.update(playback_time);
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>

#include "audio/cues.hpp"
#include "audio/rolling.hpp"
#include "audio/sounds.hpp"
#include "physics/shot.hpp"
#include "physics/vec.hpp"

namespace audio {

/// The listener (the camera), in the table frame (x east, y north, z up; unit: m).
struct Listener {
    physics::Vec3 position{-0.6, 0.635,
                           1.2};            ///< (unit: m) default: behind a 9 ft table's head rail
    physics::Vec3 forward{1.0, 0.0, -0.6};  ///< looking direction (any length)
    physics::Vec3 up{0.0, 0.0, 1.0};        ///< up direction (any length, not ∥ forward)
};

struct EngineOptions {
    std::string device;               ///< OpenAL device name; empty: the default device
    int sources = 32;                 ///< sounds that can play at once (the oldest is cut)
    double reference_distance = 1.5;  ///< full gain within this distance (unit: m)
    double rolloff = 0.6;             ///< inverse-distance rolloff beyond it (a room's reverb
                                      ///< keeps far sounds louder than 1/r)
    SoundBankOptions bank;            ///< the synthesized sounds
    CueOptions cues;                  ///< loudness, pitch and variation of the cues
    RollOptions rolling;              ///< the balls' rumble on the cloth
    int rolling_sources = 22;         ///< looping sources for the rumble: one per ball (snooker)
};

class Engine {
  public:
    /// Opens `options.device` (default: the system's). If there is none, runs silent and
    /// prints one line on stderr.
    explicit Engine(const EngineOptions& options = {});
    /// Renders into memory instead of a device (OpenAL Soft's ALC_SOFT_loopback): stereo
    /// float at `rate` Hz, read with render(). For tests and offline rendering.
    static Engine loopback(int rate, const EngineOptions& options = {});
    ~Engine();
    Engine(Engine&&) noexcept;
    Engine& operator=(Engine&&) noexcept;
    Engine(const Engine&) = delete;
    Engine& operator=(const Engine&) = delete;

    /// False when running silent (no device).
    bool active() const;

    void set_listener(const Listener& listener);
    /// Instant: muting stops every sound now; cues that fall due while muted are skipped.
    void set_muted(bool muted);
    bool muted() const { return muted_; }

    /// A new shot to play back from time 0 (stops the sounds of the previous one).
    void start(const physics::Shot& shot);
    /// Plays the cues whose time has come (call once per frame with the playback time, in s
    /// from the strike) and sets each ball's rumble from its speed then. A sound starts at the
    /// first update at or after its cue's time.
    void update(double playback_time);
    /// Once the playback has ended (its time stands still), moves the shot's clock on by `dt`
    /// (unit: s), so that the sounds after it (a potted ball reaching the return) still come.
    /// A playback that stopped more than 0.25 s before the shot's end (skipped) drops them.
    void advance(double dt);
    /// Whether the shot still has sounds to come (the app keeps its clock going until then).
    bool pending() const { return shot_.has_value() && !schedule_.finished(); }
    /// Plays one cue now (its time is ignored).
    void play(const Cue& cue);
    /// Stops every sound.
    void stop();

    /// Loopback engines only: mixes the next frames into `stereo` (interleaved left, right;
    /// its size must be even). Fills zeros otherwise.
    void render(std::span<float> stereo);

    const std::vector<Cue>& cues() const { return schedule_.cues(); }

  private:
    struct Backend;  // OpenAL device, context, buffers and sources
    Engine(std::unique_ptr<Backend> backend, const EngineOptions& options);

    std::unique_ptr<Backend> backend_;
    EngineOptions options_;
    CueSchedule schedule_;
    std::optional<physics::Shot> shot_;  ///< the shot playing, for the rumble
    double time_ = 0.0;                  ///< the last update's playback time (unit: s)
    bool muted_ = false;

    void update_rolling(double playback_time);
};

}  // namespace audio
