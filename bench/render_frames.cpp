// coolaaber-render-bench: renders the mid-game scene (the break, balls moving, shadows and
// fog on) offscreen and prints one JSON line: frame-time median and 95th percentile, fps.
//   coolaaber-render-bench [--size 1280x720] [--frames 300] [--samples 4] [--scene mid_game]
//                          [--png out.png]   (scenes: mid_game, racked, mid_roll, cue_view,
//                          ball_in_hand, aim_overhead, cushion)
#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "render/headless_context.hpp"
#include "render/image.hpp"
#include "render/renderer.hpp"
#include "render/scenes.hpp"

int main(int argc, char** argv) {
    int width = 1280, height = 720, frames = 300, samples = 4;
    bool cache_table = true;
    std::string png, scene_name = "mid_game";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool more = i + 1 < argc;
        if (a == "--size" && more) {
            if (std::sscanf(argv[++i], "%dx%d", &width, &height) != 2 || width < 1 || height < 1) {
                std::fprintf(stderr, "--size: expected WIDTHxHEIGHT, e.g. 1280x720\n");
                return 2;
            }
        } else if (a == "--frames" && more) {
            frames = std::max(1, std::atoi(argv[++i]));
        } else if (a == "--samples" && more) {
            samples = std::max(1, std::atoi(argv[++i]));
        } else if (a == "--no-table-cache") {
            cache_table = false;
        } else if (a == "--scene" && more) {
            scene_name = argv[++i];
        } else if (a == "--png" && more) {
            png = argv[++i];
        } else {
            std::fprintf(stderr,
                         "usage: coolaaber-render-bench [--size WxH] [--frames N] [--samples N] "
                         "[--scene NAME] [--no-table-cache] [--png FILE]\n");
            return 2;
        }
    }
    try {
        render::HeadlessContext context;
        const float aspect = static_cast<float>(width) / static_cast<float>(height);
        // The balls' states over the first 2 s of the break, precomputed so only drawing is timed.
        std::vector<render::DemoScene> scenes;
        const int distinct = 30;
        for (int k = 0; k < distinct; ++k) {
            if (scene_name == "mid_game")
                scenes.push_back(render::mid_game_scene(aspect, 0.05 + 2.0 * k / distinct));
            else if (scene_name == "racked")
                scenes.push_back(render::racked_scene(aspect));
            else if (scene_name == "mid_roll")
                scenes.push_back(render::mid_roll_scene(aspect));
            else if (scene_name == "cue_view")
                scenes.push_back(render::cue_view_scene(aspect));
            else if (scene_name == "ball_in_hand")
                scenes.push_back(render::ball_in_hand_scene(aspect));
            else if (scene_name == "aim_overhead")
                scenes.push_back(render::aim_overhead_scene(aspect));
            else if (scene_name == "cushion")
                scenes.push_back(render::cushion_scene(aspect));
            else {
                std::fprintf(stderr,
                             "--scene: expected mid_game, racked, mid_roll, cue_view, "
                             "ball_in_hand, aim_overhead or cushion\n");
                return 2;
            }
        }
        render::RenderSettings settings;
        settings.cache_table = cache_table;
        render::Renderer renderer(scenes.front().table, scenes.front().ball_radius, settings);
        render::OffscreenTarget target(width, height, samples);
        std::vector<double> ms;
        for (int f = 0; f < frames + 5; ++f) {
            const auto start = std::chrono::steady_clock::now();
            target.bind();
            renderer.draw(scenes[static_cast<std::size_t>(f % distinct)].frame(), width, height);
            target.resolve();
            glFinish();
            const auto end = std::chrono::steady_clock::now();
            if (f >= 5)
                ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
        }
        if (!png.empty()) render::write_png(png, render::read_pixels(width, height));
        std::sort(ms.begin(), ms.end());
        const double median = ms[ms.size() / 2];
        const double p95 = ms[std::min(ms.size() - 1, ms.size() * 95 / 100)];
        std::printf(
            "{\"size\":\"%dx%d\",\"frames\":%d,\"samples\":%d,\"table_cache\":%s,\"renderer\":\"%"
            "s\",\"median_ms\":%.3f,"
            "\"p95_ms\":%.3f,\"fps\":%.1f}\n",
            width, height, frames, target.samples(), cache_table ? "true" : "false",
            context.renderer_name().c_str(), median, p95, 1000.0 / median);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "coolaaber-render-bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
