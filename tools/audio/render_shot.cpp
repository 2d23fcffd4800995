// coolaaber-audio-render: the sound of a standard scene, for a person to listen to.
//   coolaaber-audio-render [SCENE [OUT.wav]]   renders through the loopback device to a WAV file
//   coolaaber-audio-render --play [SCENE]      plays it on the default device in real time
// SCENE is a physics standard scene: break, cut, long_roll, bank (default: break).
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "audio/engine.hpp"
#include "audio/wav.hpp"
#include "physics/scenes.hpp"
#include "physics/simulate.hpp"

namespace {

physics::Shot simulate_scene(const std::string& name) {
    const physics::Params p;
    const physics::Scene s = physics::standard_scene(name, p);
    return physics::simulate(physics::build_table(s.table), p, s.balls, &s.stroke);
}

double length_of(const physics::Shot& shot) {
    return (shot.events().empty() ? 0.0 : shot.events().back().time) + 1.5;
}

int play(const physics::Shot& shot) {
    audio::Engine engine;
    if (!engine.active()) return 0;  // it said why on stderr, once
    engine.start(shot);
    const auto t0 = std::chrono::steady_clock::now();
    for (double t = 0.0; t < length_of(shot);) {
        engine.update(t);
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    return 0;
}

int render(const physics::Shot& shot, const std::string& out) {
    constexpr int kRate = 48000, kChunk = 48;  // 1 ms per update
    audio::Engine engine = audio::Engine::loopback(kRate);
    if (!engine.active()) return 1;
    engine.start(shot);
    const auto frames = static_cast<std::size_t>(length_of(shot) * kRate);
    std::vector<float> samples(2 * frames);
    for (std::size_t f = 0; f < frames; f += kChunk) {
        engine.update(static_cast<double>(f) / kRate);
        const std::size_t n = std::min<std::size_t>(kChunk, frames - f);
        engine.render({samples.data() + 2 * f, 2 * n});
    }
    if (!audio::write_wav(out, samples, 2, kRate)) {
        std::fprintf(stderr, "could not write %s\n", out.c_str());
        return 1;
    }
    std::printf("%s: %zu cues, %.2f s\n", out.c_str(), engine.cues().size(),
                static_cast<double>(frames) / kRate);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    const bool live = !args.empty() && args[0] == "--play";
    if (live) args.erase(args.begin());
    const std::string scene = args.size() > 0 ? args[0] : "break";
    try {
        const physics::Shot shot = simulate_scene(scene);
        return live ? play(shot) : render(shot, args.size() > 1 ? args[1] : scene + ".wav");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s (scenes: break, cut, long_roll, bank)\n", e.what());
        return 2;
    }
}
