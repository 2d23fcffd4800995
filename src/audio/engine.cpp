// The OpenAL Soft edge. Everything here is a thin translation of cues into sources; the sounds
// and the cues are made in pure C++ (sounds.cpp, cues.cpp).
#include "audio/engine.hpp"

#define AL_ALEXT_PROTOTYPES
#include <AL/al.h>
#include <AL/alc.h>
#include <AL/alext.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <vector>

#if defined(__unix__) && !defined(__EMSCRIPTEN__)
#include <fcntl.h>
#include <unistd.h>
#define COOLAABER_AUDIO_QUIET_OPEN 1
#endif

namespace audio {
namespace {

/// While it lives, stderr goes to /dev/null: with no sound card, ALSA and OpenAL Soft print
/// a dozen lines while failing to open one, and the promise is one line. Set ALSOFT_LOGLEVEL
/// to see them.
class QuietStderr {
  public:
    QuietStderr() {
#ifdef COOLAABER_AUDIO_QUIET_OPEN
        if (std::getenv("ALSOFT_LOGLEVEL") != nullptr) return;
        std::fflush(stderr);
        saved_ = dup(2);
        const int null = open("/dev/null", O_WRONLY);
        if (null >= 0) {
            dup2(null, 2);
            close(null);
        }
#endif
    }
    ~QuietStderr() {
#ifdef COOLAABER_AUDIO_QUIET_OPEN
        if (saved_ < 0) return;
        std::fflush(stderr);
        dup2(saved_, 2);
        close(saved_);
#endif
    }
    QuietStderr(const QuietStderr&) = delete;
    QuietStderr& operator=(const QuietStderr&) = delete;

  private:
    [[maybe_unused]] int saved_ = -1;
};

void say_silent(const char* why) {
    std::fprintf(stderr, "audio: %s; running silent\n", why);
}

}  // namespace

struct Engine::Backend {
    ALCdevice* device = nullptr;
    ALCcontext* context = nullptr;
    bool loopback = false;
    int variants = 1;
    std::vector<ALuint> buffers;  // kind × variants
    std::vector<ALuint> sources;
    std::vector<ALuint> roll_sources;       // looping, one per ball of the shot
    std::vector<float> roll_gain;           // each roll source's gain at the last update
    std::vector<std::uint64_t> started_at;  // per source: order in which it was started
    std::uint64_t started = 0;

    Backend(ALCdevice* d, ALCcontext* c, bool is_loopback)
        : device(d), context(c), loopback(is_loopback) {}
    Backend(const Backend&) = delete;
    Backend& operator=(const Backend&) = delete;

    /// OpenAL calls act on the current context; engines in one process take turns.
    void bind() const {
        if (alcGetCurrentContext() != context) alcMakeContextCurrent(context);
    }

    void load(const SoundBank& bank, const EngineOptions& o) {
        bind();
        variants = bank.variants();
        buffers.resize(static_cast<std::size_t>(kSoundKindCount * variants));
        alGenBuffers(static_cast<ALsizei>(buffers.size()), buffers.data());
        for (int k = 0; k < kSoundKindCount; ++k) {
            for (int v = 0; v < variants; ++v) {
                const Pcm& pcm = bank.get(static_cast<SoundKind>(k), v);
                const std::vector<std::int16_t> data = to_int16(pcm);
                alBufferData(buffers[static_cast<std::size_t>(k * variants + v)], AL_FORMAT_MONO16,
                             data.data(), static_cast<ALsizei>(data.size() * 2), pcm.rate);
            }
        }
        sources.resize(static_cast<std::size_t>(o.sources > 0 ? o.sources : 1));
        alGenSources(static_cast<ALsizei>(sources.size()), sources.data());
        started_at.assign(sources.size(), 0);
        roll_sources.resize(static_cast<std::size_t>(std::max(0, o.rolling_sources)));
        if (!roll_sources.empty())
            alGenSources(static_cast<ALsizei>(roll_sources.size()), roll_sources.data());
        roll_gain.assign(roll_sources.size(), 0.0f);
        alDistanceModel(AL_INVERSE_DISTANCE_CLAMPED);
        // Each ball its own variant of the rumble, so that balls rolling together don't sum
        // into one louder, phasing noise.
        for (std::size_t i = 0; i < roll_sources.size(); ++i) {
            const auto v = static_cast<int>(i) % variants;
            const auto k = static_cast<int>(SoundKind::cloth_roll);
            alSourcei(roll_sources[i], AL_BUFFER,
                      static_cast<ALint>(buffers[static_cast<std::size_t>(k * variants + v)]));
            alSourcei(roll_sources[i], AL_LOOPING, AL_TRUE);
        }
        for (ALuint s : all_sources()) {
            alSourcef(s, AL_REFERENCE_DISTANCE, static_cast<ALfloat>(o.reference_distance));
            alSourcef(s, AL_ROLLOFF_FACTOR, static_cast<ALfloat>(o.rolloff));
            alSourcei(s, AL_SOURCE_RELATIVE, AL_FALSE);
        }
    }

    std::vector<ALuint> all_sources() const {
        std::vector<ALuint> all = sources;
        all.insert(all.end(), roll_sources.begin(), roll_sources.end());
        return all;
    }

    /// Sets ball `i`'s rumble; a source silent for two updates in a row is stopped (the
    /// gain goes to 0 first, so that stopping it makes no click).
    void roll(std::size_t i, const Roll& r) {
        const ALuint s = roll_sources[i];
        if (r.gain <= 0.0f && roll_gain[i] <= 0.0f) {
            alSourceStop(s);
            return;
        }
        alSourcef(s, AL_GAIN, r.gain);
        alSourcef(s, AL_PITCH, r.pitch);
        alSource3f(s, AL_POSITION, static_cast<ALfloat>(r.position.x),
                   static_cast<ALfloat>(r.position.y), static_cast<ALfloat>(r.position.z));
        ALint state = AL_STOPPED;
        alGetSourcei(s, AL_SOURCE_STATE, &state);
        if (state != AL_PLAYING) alSourcePlay(s);
        roll_gain[i] = r.gain;
    }

    void stop_all() {
        const std::vector<ALuint> all = all_sources();
        alSourceStopv(static_cast<ALsizei>(all.size()), all.data());
        std::fill(roll_gain.begin(), roll_gain.end(), 0.0f);
    }

    /// A free source, else the one started longest ago.
    std::size_t pick_source() const {
        std::size_t oldest = 0;
        for (std::size_t i = 0; i < sources.size(); ++i) {
            ALint state = AL_STOPPED;
            alGetSourcei(sources[i], AL_SOURCE_STATE, &state);
            if (state != AL_PLAYING) return i;
            if (started_at[i] < started_at[oldest]) oldest = i;
        }
        return oldest;
    }

    ~Backend() {
        bind();
        const std::vector<ALuint> all = all_sources();
        if (!all.empty()) {
            alSourceStopv(static_cast<ALsizei>(all.size()), all.data());
            alDeleteSources(static_cast<ALsizei>(all.size()), all.data());
        }
        if (!buffers.empty()) alDeleteBuffers(static_cast<ALsizei>(buffers.size()), buffers.data());
        alcMakeContextCurrent(nullptr);
        alcDestroyContext(context);
        alcCloseDevice(device);
    }
};

Engine::Engine(const EngineOptions& options) : options_(options) {
    ALCdevice* device = nullptr;
    ALCcontext* context = nullptr;
    {
        QuietStderr quiet;
        device = alcOpenDevice(options.device.empty() ? nullptr : options.device.c_str());
        if (device != nullptr) context = alcCreateContext(device, nullptr);
    }
    if (device == nullptr || context == nullptr) {
        if (device != nullptr) alcCloseDevice(device);
        say_silent("no audio device could be opened");
        return;
    }
    backend_ = std::make_unique<Backend>(device, context, false);
    backend_->load(make_sound_bank(options.bank), options);
    set_listener({});
}

Engine::Engine(std::unique_ptr<Backend> backend, const EngineOptions& options)
    : backend_(std::move(backend)), options_(options) {
    if (!backend_) return;
    backend_->load(make_sound_bank(options.bank), options);
    set_listener({});
}

Engine Engine::loopback(int rate, const EngineOptions& options) {
    if (alcIsExtensionPresent(nullptr, "ALC_SOFT_loopback") == ALC_FALSE) {
        say_silent("OpenAL has no loopback device (ALC_SOFT_loopback)");
        return Engine(nullptr, options);
    }
    ALCdevice* device = alcLoopbackOpenDeviceSOFT(nullptr);
    if (device == nullptr || alcIsRenderFormatSupportedSOFT(device, rate, ALC_STEREO_SOFT,
                                                            ALC_FLOAT_SOFT) == ALC_FALSE) {
        if (device != nullptr) alcCloseDevice(device);
        say_silent("the OpenAL loopback device can't render stereo float");
        return Engine(nullptr, options);
    }
    // Plain stereo panning (no HRTF), so that left/right follow the source's direction.
    const ALCint attributes[] = {ALC_FORMAT_CHANNELS_SOFT,
                                 ALC_STEREO_SOFT,
                                 ALC_FORMAT_TYPE_SOFT,
                                 ALC_FLOAT_SOFT,
                                 ALC_FREQUENCY,
                                 rate,
                                 ALC_HRTF_SOFT,
                                 ALC_FALSE,
                                 0};
    ALCcontext* context = alcCreateContext(device, attributes);
    if (context == nullptr) {
        alcCloseDevice(device);
        say_silent("the OpenAL loopback context could not be created");
        return Engine(nullptr, options);
    }
    return Engine(std::make_unique<Backend>(device, context, true), options);
}

Engine::~Engine() = default;
Engine::Engine(Engine&&) noexcept = default;
Engine& Engine::operator=(Engine&&) noexcept = default;

bool Engine::active() const {
    return backend_ != nullptr;
}

void Engine::set_listener(const Listener& l) {
    if (!backend_) return;
    backend_->bind();
    alListener3f(AL_POSITION, static_cast<ALfloat>(l.position.x),
                 static_cast<ALfloat>(l.position.y), static_cast<ALfloat>(l.position.z));
    const ALfloat orientation[] = {
        static_cast<ALfloat>(l.forward.x), static_cast<ALfloat>(l.forward.y),
        static_cast<ALfloat>(l.forward.z), static_cast<ALfloat>(l.up.x),
        static_cast<ALfloat>(l.up.y),      static_cast<ALfloat>(l.up.z)};
    alListenerfv(AL_ORIENTATION, orientation);
}

void Engine::set_muted(bool muted) {
    muted_ = muted;
    if (!backend_) return;
    backend_->bind();
    alListenerf(AL_GAIN, muted ? 0.0f : 1.0f);
    if (muted) stop();
}

void Engine::start(const physics::Shot& shot) {
    CueOptions cue_options = options_.cues;
    cue_options.variants = options_.bank.variants;
    schedule_ = CueSchedule(cues_for_shot(shot, cue_options));
    shot_ = shot;
    time_ = 0.0;
    stop();
}

void Engine::update(double playback_time) {
    // Always advance, muted or silent, so that unmuting does not replay a backlog.
    time_ = playback_time;
    const std::span<const Cue> due = schedule_.due(playback_time);
    if (!backend_ || muted_) return;
    for (const Cue& c : due) play(c);
    update_rolling(playback_time);
}

void Engine::advance(double dt) {
    if (!shot_) return;
    // A playback cut short (skipped to its end) has no tail: its later sounds are dropped.
    const double end =
        shot_->rest_time().value_or(shot_->events().empty() ? 0.0 : shot_->events().back().time);
    if (time_ < end - 0.25) {
        schedule_ = CueSchedule();
        shot_.reset();
        stop();
        return;
    }
    update(time_ + dt);
}

void Engine::update_rolling(double playback_time) {
    if (!backend_ || muted_ || !shot_) return;
    Backend& b = *backend_;
    b.bind();
    const std::vector<Roll> rolls = rolling_at(*shot_, playback_time, options_.rolling);
    for (std::size_t i = 0; i < rolls.size() && i < b.roll_sources.size(); ++i) b.roll(i, rolls[i]);
}

void Engine::play(const Cue& cue) {
    if (!backend_ || muted_ || cue.gain <= 0.0f) return;
    Backend& b = *backend_;
    b.bind();
    const std::size_t i = b.pick_source();
    const ALuint s = b.sources[i];
    alSourceStop(s);
    const int variant = ((cue.variant % b.variants) + b.variants) % b.variants;
    const auto buffer =
        b.buffers[static_cast<std::size_t>(static_cast<int>(cue.kind) * b.variants + variant)];
    alSourcei(s, AL_BUFFER, static_cast<ALint>(buffer));
    alSourcef(s, AL_GAIN, cue.gain);
    alSourcef(s, AL_PITCH, cue.pitch);
    alSource3f(s, AL_POSITION, static_cast<ALfloat>(cue.position.x),
               static_cast<ALfloat>(cue.position.y), static_cast<ALfloat>(cue.position.z));
    alSourcePlay(s);
    b.started_at[i] = ++b.started;
}

void Engine::stop() {
    if (!backend_) return;
    backend_->bind();
    backend_->stop_all();
}

void Engine::render(std::span<float> stereo) {
    if (!backend_ || !backend_->loopback) {
        std::fill(stereo.begin(), stereo.end(), 0.0f);
        return;
    }
    backend_->bind();
    alcRenderSamplesSOFT(backend_->device, stereo.data(), static_cast<ALCsizei>(stereo.size() / 2));
}

}  // namespace audio
