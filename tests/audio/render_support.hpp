// Shared by the audio tests: simulated scenes, loopback renders of a shot, and measures of
// the rendered sound (onsets, per-channel energy).
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "audio/engine.hpp"
#include "physics/cue_strike.hpp"
#include "physics/scenes.hpp"
#include "physics/simulate.hpp"

namespace audio::test {

inline constexpr int kRate = 48000;  // loopback sample rate (unit: Hz)
inline constexpr int kChunk = 48;    // frames rendered per update: 1 ms, the scheduling step

/// A standard scene, optionally with the cue-ball speed changed (unit: m/s; 0 keeps it).
inline physics::Shot scene_shot(std::string_view name, double ball_speed = 0.0) {
    const physics::Params p;
    physics::Scene s = physics::standard_scene(name, p);
    if (ball_speed > 0.0) s.stroke.speed = physics::cue_speed_for_ball_speed(p, ball_speed);
    return physics::simulate(physics::build_table(s.table), p, s.balls, &s.stroke);
}

/// Interleaved stereo.
struct Stereo {
    std::vector<float> samples;
    std::size_t frames() const { return samples.size() / 2; }
    float left(std::size_t i) const { return samples[2 * i]; }
    float right(std::size_t i) const { return samples[2 * i + 1]; }
};

/// Plays `shot` from time 0 for `seconds`, calling update() every kChunk frames as a game
/// loop would, and returns what the loopback device rendered.
inline Stereo render_shot(Engine& engine, const physics::Shot& shot, double seconds) {
    engine.start(shot);
    Stereo out;
    const auto frames = static_cast<std::size_t>(seconds * kRate);
    out.samples.assign(frames * 2, 0.0f);
    for (std::size_t f = 0; f < frames; f += kChunk) {
        engine.update(static_cast<double>(f) / kRate);
        const std::size_t n = std::min<std::size_t>(kChunk, frames - f);
        engine.render({out.samples.data() + 2 * f, 2 * n});
    }
    return out;
}

/// Renders `seconds` of whatever is playing.
inline Stereo render_for(Engine& engine, double seconds) {
    Stereo out;
    out.samples.assign(static_cast<std::size_t>(seconds * kRate) * 2, 0.0f);
    engine.render(out.samples);
    return out;
}

/// Onsets (unit: s): a 1 ms frame whose energy is over `floor` and more than `rise` times
/// the largest of the previous 10 frames; refined to the first sample whose step exceeds 20 %
/// of the largest step in the following 3 ms. A new onset needs `gap` since the last one.
inline std::vector<double> onsets(const Stereo& s, double floor = 1e-8, double rise = 10.0,
                                  double gap = 0.025) {
    const std::size_t frame = kRate / 1000;
    const std::size_t count = s.frames() / frame;
    // Energy of the first difference: it weighs an attack's high frequencies over the low
    // ringing and rumble of earlier sounds (a pre-emphasis, as onset detectors use).
    std::vector<double> energy(count, 0.0);
    for (std::size_t k = 0; k < count; ++k) {
        for (std::size_t i = std::max<std::size_t>(1, k * frame); i < (k + 1) * frame; ++i) {
            const double dl = double(s.left(i)) - s.left(i - 1);
            const double dr = double(s.right(i)) - s.right(i - 1);
            energy[k] += dl * dl + dr * dr;
        }
        energy[k] /= double(frame);
    }
    std::vector<double> found;
    for (std::size_t k = 0; k < count; ++k) {
        double before = 0.0;
        for (std::size_t j = (k >= 10 ? k - 10 : 0); j < k; ++j)
            before = std::max(before, energy[j]);
        if (energy[k] <= floor || energy[k] <= rise * before) continue;
        const std::size_t lo = std::max<std::size_t>(1, (k > 0 ? k - 1 : 0) * frame);
        const std::size_t hi = std::min(s.frames(), (k + 3) * frame);
        const auto step = [&](std::size_t i) {
            return std::max(std::abs(s.left(i) - s.left(i - 1)),
                            std::abs(s.right(i) - s.right(i - 1)));
        };
        float top = 0.0f;
        for (std::size_t i = std::max(lo, k * frame); i < hi; ++i) top = std::max(top, step(i));
        std::size_t first = k * frame;
        for (std::size_t i = lo; i < hi; ++i) {
            if (step(i) > 0.2f * top) {
                first = i;
                break;
            }
        }
        const double t = double(first) / kRate;
        if (!found.empty() && t - found.back() < gap) continue;
        found.push_back(t);
    }
    return found;
}

/// Largest |sample| of either channel within [t0, t1) (unit: s).
inline float peak_between(const Stereo& s, double t0, double t1) {
    float top = 0.0f;
    const auto a = static_cast<std::size_t>(std::max(0.0, t0) * kRate);
    const auto b = std::min(s.frames(), static_cast<std::size_t>(t1 * kRate));
    for (std::size_t i = a; i < b; ++i)
        top = std::max({top, std::abs(s.left(i)), std::abs(s.right(i))});
    return top;
}

/// Energy of each channel over the whole render.
inline std::pair<double, double> channel_energy(const Stereo& s) {
    double l = 0.0, r = 0.0;
    for (std::size_t i = 0; i < s.frames(); ++i) {
        l += double(s.left(i)) * s.left(i);
        r += double(s.right(i)) * s.right(i);
    }
    return {l, r};
}

/// A path next to the test program (the build folder), for renders a person can listen to.
inline std::string output_path(const std::string& name) {
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return name;
    return (exe.parent_path() / name).string();
}

}  // namespace audio::test
