// Building blocks of the synthesis: modal resonators (damped sinusoids), filtered noise bursts
// and slow envelopes, added into a mono buffer. Modal synthesis of impact sounds follows
// van den Doel & Pai, "The sounds of physical shapes" (Presence 7(4), 1998): an object struck
// rings as a sum of exponentially decaying modes; the contact adds a short noise transient.
#pragma once

#include "audio/pcm.hpp"
#include "audio/rng.hpp"

namespace audio::synth {

/// A white-noise sample, uniform in [−1, 1].
double white(Rng& rng);

/// One mode: a(t) = amp · e^(−t/decay) · sin(2π·freq·t + phase), from `start` on.
struct Mode {
    double freq = 1000.0;  ///< (unit: Hz)
    double decay = 0.01;   ///< time constant of the amplitude (unit: s)
    double amp = 1.0;      ///< initial amplitude (unit: full scale)
};

/// How fast the contact builds up: the sum is multiplied by 1 − e^(−t/attack). A hard contact
/// (phenolic on phenolic) takes a few tens of µs, a rubber cushion about a millisecond.
struct Contact {
    double start = 0.0;    ///< when the contact begins (unit: s)
    double attack = 1e-4;  ///< rise time constant (unit: s)
};

/// Adds the modes, struck at contact.start, with random phases from `rng`.
void add_modes(Pcm& out, const Contact& contact, const Mode* modes, int count, Rng& rng);

/// A second-order filter (RBJ "Audio EQ Cookbook" biquads), direct form I.
class Biquad {
  public:
    static Biquad lowpass(double rate, double freq, double q);
    static Biquad highpass(double rate, double freq, double q);
    static Biquad bandpass(double rate, double freq, double q);  ///< 0 dB peak gain
    double operator()(double x);

  private:
    double b0_ = 1, b1_ = 0, b2_ = 0, a1_ = 0, a2_ = 0;
    double x1_ = 0, x2_ = 0, y1_ = 0, y2_ = 0;
};

/// A burst of filtered white noise: amp · e^(−t/decay), from contact.start, `length` long.
void add_noise_burst(Pcm& out, const Contact& contact, double decay, double amp, Biquad filter,
                     Rng& rng, double length);

/// Filtered noise under a smooth envelope: a raised-cosine rise of `rise`, a hold, and a
/// raised-cosine fall of `fall`, starting at `start`; the amplitude wobbles by `wobble` (0–1)
/// at `wobble_hz`, as a rolling ball's rumble does once per turn.
struct Rumble {
    double start = 0.0;      ///< (unit: s)
    double rise = 0.2;       ///< (unit: s)
    double hold = 0.3;       ///< (unit: s)
    double fall = 0.4;       ///< (unit: s)
    double amp = 0.2;        ///< (unit: full scale)
    double wobble = 0.3;     ///< depth of the amplitude modulation, 0–1
    double wobble_hz = 3.0;  ///< (unit: Hz)
};
/// The noise goes through `band`, then through `smooth` (a low-pass that keeps hiss out).
void add_rumble(Pcm& out, const Rumble& rumble, Biquad band, Biquad smooth, Rng& rng);

}  // namespace audio::synth
