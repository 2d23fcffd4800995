// coolaaber-render-bench: renders the mid-game scene (the break, balls moving, shadows and
// fog on) offscreen and prints one JSON line: frame-time median and 95th percentile, fps.
//   coolaaber-render-bench [--size 1280x720] [--frames 300] [--samples 4] [--scene mid_game]
//                          [--no-table-cache] [--moving-camera] [--moving-scale X]
//                          [--png out.png]   (scenes: mid_game, racked, mid_roll, cue_view,
//                          ball_in_hand, aim_overhead, cushion, rail_view, raised_cue, pocket,
//                          room)
// --moving-camera turns the eye a little every frame (aiming in the cue-ball view): the frame
// is then drawn smaller and scaled up: at RenderSettings::moving_scale, stepping down toward
// moving_scale_lowest while frames are over their budget, as in the game; --moving-scale X
// fixes it at X.
#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/headless_context.hpp"
#include "render/image.hpp"
#include "render/renderer.hpp"
#include "render/scenes.hpp"

namespace {

struct Options {
    int width = 1280, height = 720, frames = 300, samples = 4;
    bool cache_table = true;
    bool moving_camera = false;  ///< the eye turns round the target a little every frame
    float moving_scale = render::RenderSettings{}.moving_scale;
    bool fixed_scale = false;  ///< --moving-scale given: no adapting to the frame time
    std::string png, scene = "mid_game";
};

// The options, or nothing after a message on stderr.
std::optional<Options> parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool more = i + 1 < argc;
        if (a == "--size" && more) {
            if (std::sscanf(argv[++i], "%dx%d", &o.width, &o.height) != 2 || o.width < 1 ||
                o.height < 1) {
                std::fprintf(stderr, "--size: expected WIDTHxHEIGHT, e.g. 1280x720\n");
                return std::nullopt;
            }
        } else if (a == "--frames" && more) {
            o.frames = std::max(1, std::atoi(argv[++i]));
        } else if (a == "--samples" && more) {
            o.samples = std::max(1, std::atoi(argv[++i]));
        } else if (a == "--no-table-cache") {
            o.cache_table = false;
        } else if (a == "--moving-camera") {
            o.moving_camera = true;
        } else if (a == "--moving-scale" && more) {
            o.moving_scale = std::clamp(static_cast<float>(std::atof(argv[++i])), 0.1f, 1.0f);
            o.fixed_scale = true;
        } else if (a == "--scene" && more) {
            o.scene = argv[++i];
        } else if (a == "--png" && more) {
            o.png = argv[++i];
        } else {
            std::fprintf(stderr,
                         "usage: coolaaber-render-bench [--size WxH] [--frames N] [--samples N] "
                         "[--scene NAME] [--no-table-cache] [--moving-camera] "
                         "[--moving-scale X] [--png FILE]\n");
            return std::nullopt;
        }
    }
    return o;
}

// The scene by name at moment k of `distinct`; an unknown name throws std::invalid_argument.
render::DemoScene scene_named(const std::string& name, float aspect, int k, int distinct) {
    if (name == "mid_game") return render::mid_game_scene(aspect, 0.05 + 2.0 * k / distinct);
    if (name == "racked") return render::racked_scene(aspect);
    if (name == "mid_roll") return render::mid_roll_scene(aspect);
    if (name == "cue_view") return render::cue_view_scene(aspect);
    if (name == "ball_in_hand") return render::ball_in_hand_scene(aspect);
    if (name == "aim_overhead") return render::aim_overhead_scene(aspect);
    if (name == "cushion") return render::cushion_scene(aspect);
    if (name == "rail_view") return render::rail_view_scene(aspect);
    if (name == "raised_cue") return render::raised_cue_scene(aspect);
    if (name == "pocket") return render::pocket_scene(aspect);
    if (name == "room") return render::room_scene(aspect);
    throw std::invalid_argument(
        "--scene: expected mid_game, racked, mid_roll, cue_view, ball_in_hand, aim_overhead, "
        "cushion, rail_view, raised_cue, pocket or room");
}

// Draws the scenes in turn (after 5 frames of warm-up); the frame times (unit: ms), sorted.
std::vector<double> frame_times(const Options& o, const std::vector<render::DemoScene>& scenes,
                                render::OffscreenTarget& target, float& reached) {
    render::RenderSettings settings;
    settings.cache_table = o.cache_table;
    settings.moving_scale = o.moving_scale;
    if (o.fixed_scale) settings.moving_scale_lowest = o.moving_scale;
    render::Renderer renderer(scenes.front().table, scenes.front().ball_radius, settings);
    std::vector<double> ms;
    for (int f = 0; f < o.frames + 5; ++f) {
        const auto start = std::chrono::steady_clock::now();
        target.bind();
        render::FrameView view = scenes[static_cast<std::size_t>(f) % scenes.size()].frame();
        if (o.moving_camera) {
            // A fifth of a degree a frame round the vertical through the target, as when aiming.
            const glm::vec3 arm = view.camera.eye - view.camera.target;
            const float a = 0.0035f * static_cast<float>(f), c = std::cos(a), s = std::sin(a);
            view.camera.eye =
                view.camera.target + glm::vec3(c * arm.x - s * arm.y, s * arm.x + c * arm.y, arm.z);
        }
        renderer.draw(view, o.width, o.height);
        target.resolve();
        glFinish();
        const auto end = std::chrono::steady_clock::now();
        if (f >= 5) ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
    }
    reached = renderer.moving_scale();
    std::sort(ms.begin(), ms.end());
    return ms;
}

}  // namespace

int main(int argc, char** argv) {
    const std::optional<Options> o = parse(argc, argv);
    if (!o) return 2;
    try {
        render::HeadlessContext context;
        const float aspect = static_cast<float>(o->width) / static_cast<float>(o->height);
        // The balls' states over the first 2 s of the break, precomputed so only drawing is timed.
        std::vector<render::DemoScene> scenes;
        const int distinct = 30;
        for (int k = 0; k < distinct; ++k)
            scenes.push_back(scene_named(o->scene, aspect, k, distinct));
        render::OffscreenTarget target(o->width, o->height, o->samples);
        float reached = 1.0f;
        const std::vector<double> ms = frame_times(*o, scenes, target, reached);
        if (!o->png.empty()) render::write_png(o->png, render::read_pixels(o->width, o->height));
        const double median = ms[ms.size() / 2];
        const double p95 = ms[std::min(ms.size() - 1, ms.size() * 95 / 100)];
        std::printf(
            "{\"size\":\"%dx%d\",\"frames\":%d,\"samples\":%d,\"table_cache\":%s,"
            "\"moving_camera\":%s,\"moving_scale\":%.2f,\"adaptive\":%s,\"scale_reached\":%.4f,"
            "\"renderer\":\"%s\",\"median_ms\":%.3f,\"p95_ms\":%.3f,\"fps\":%.1f}\n",
            o->width, o->height, o->frames, target.samples(), o->cache_table ? "true" : "false",
            o->moving_camera ? "true" : "false", o->moving_scale, o->fixed_scale ? "false" : "true",
            reached, context.renderer_name().c_str(), median, p95, 1000.0 / median);
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "coolaaber-render-bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
