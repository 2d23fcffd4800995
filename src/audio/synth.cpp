#include "audio/synth.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace audio::synth {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

std::size_t index_at(const Pcm& pcm, double t) {
    return static_cast<std::size_t>(std::max(0.0, std::round(t * pcm.rate)));
}

}  // namespace

double white(Rng& rng) {
    return rng.uniform(-1.0, 1.0);
}

void add_modes(Pcm& out, const Contact& contact, const Mode* modes, int count, Rng& rng) {
    const std::size_t first = index_at(out, contact.start);
    const double dt = 1.0 / out.rate;
    for (int m = 0; m < count; ++m) {
        const Mode& mode = modes[m];
        if (mode.freq * 2.0 >= out.rate) continue;  // above Nyquist: would alias
        const double phase = rng.uniform(0.0, kTwoPi);
        // Stop once the mode has decayed by 100 dB.
        const double life = mode.decay * std::log(1e5);
        const std::size_t last = std::min(out.samples.size(), first + index_at(out, life));
        // By recurrence (a rotation and two decays a sample) instead of an exp, an exp and a
        // sin a sample: ten times faster, the sound bank being made before the first frame.
        const double turn = kTwoPi * mode.freq * dt, cos_turn = std::cos(turn),
                     sin_turn = std::sin(turn);
        const double fade = std::exp(-dt / mode.decay), settle = std::exp(-dt / contact.attack);
        double x = std::cos(phase), y = std::sin(phase), amp = mode.amp, unrisen = 1.0;
        for (std::size_t i = first; i < last; ++i) {
            out.samples[i] += static_cast<float>(amp * (1.0 - unrisen) * y);
            const double nx = x * cos_turn - y * sin_turn;
            y = x * sin_turn + y * cos_turn;
            x = nx;
            amp *= fade;
            unrisen *= settle;
        }
    }
}

Biquad Biquad::lowpass(double rate, double freq, double q) {
    const double w = kTwoPi * freq / rate, c = std::cos(w), alpha = std::sin(w) / (2.0 * q);
    const double a0 = 1.0 + alpha;
    Biquad f;
    f.b0_ = (1.0 - c) / 2.0 / a0;
    f.b1_ = (1.0 - c) / a0;
    f.b2_ = f.b0_;
    f.a1_ = -2.0 * c / a0;
    f.a2_ = (1.0 - alpha) / a0;
    return f;
}

Biquad Biquad::highpass(double rate, double freq, double q) {
    const double w = kTwoPi * freq / rate, c = std::cos(w), alpha = std::sin(w) / (2.0 * q);
    const double a0 = 1.0 + alpha;
    Biquad f;
    f.b0_ = (1.0 + c) / 2.0 / a0;
    f.b1_ = -(1.0 + c) / a0;
    f.b2_ = f.b0_;
    f.a1_ = -2.0 * c / a0;
    f.a2_ = (1.0 - alpha) / a0;
    return f;
}

Biquad Biquad::bandpass(double rate, double freq, double q) {
    const double w = kTwoPi * freq / rate, c = std::cos(w), alpha = std::sin(w) / (2.0 * q);
    const double a0 = 1.0 + alpha;
    Biquad f;
    f.b0_ = alpha / a0;
    f.b1_ = 0.0;
    f.b2_ = -alpha / a0;
    f.a1_ = -2.0 * c / a0;
    f.a2_ = (1.0 - alpha) / a0;
    return f;
}

double Biquad::operator()(double x) {
    const double y = b0_ * x + b1_ * x1_ + b2_ * x2_ - a1_ * y1_ - a2_ * y2_;
    x2_ = x1_;
    x1_ = x;
    y2_ = y1_;
    y1_ = y;
    return y;
}

void add_noise_burst(Pcm& out, const Contact& contact, double decay, double amp, Biquad filter,
                     Rng& rng, double length) {
    const std::size_t first = index_at(out, contact.start);
    const std::size_t last = std::min(out.samples.size(), first + index_at(out, length));
    const double dt = 1.0 / out.rate;
    for (std::size_t i = first; i < last; ++i) {
        const double t = static_cast<double>(i - first) * dt;
        const double env = (1.0 - std::exp(-t / contact.attack)) * std::exp(-t / decay);
        out.samples[i] += static_cast<float>(amp * env * filter(white(rng)));
    }
}

void add_rumble(Pcm& out, const Rumble& r, Biquad band, Biquad smooth, Rng& rng) {
    const std::size_t first = index_at(out, r.start);
    const std::size_t last =
        std::min(out.samples.size(), first + index_at(out, r.rise + r.hold + r.fall));
    const double dt = 1.0 / out.rate;
    const double wobble_phase = rng.uniform(0.0, kTwoPi);
    for (std::size_t i = first; i < last; ++i) {
        const double t = static_cast<double>(i - first) * dt;
        double env = 1.0;
        if (t < r.rise) {
            env = 0.5 - 0.5 * std::cos(std::numbers::pi * t / r.rise);
        } else if (t > r.rise + r.hold) {
            const double u = std::min(1.0, (t - r.rise - r.hold) / r.fall);
            env = 0.5 + 0.5 * std::cos(std::numbers::pi * u);
        }
        const double wobble =
            1.0 - r.wobble * (0.5 + 0.5 * std::sin(kTwoPi * r.wobble_hz * t + wobble_phase));
        out.samples[i] += static_cast<float>(r.amp * env * wobble * smooth(band(white(rng))));
    }
}

}  // namespace audio::synth
