// Golden-image tests: fixed scenes rendered headless (EGL on Mesa llvmpipe) into a
// multisampled framebuffer and compared with the PNGs in tests/render/data with a small
// per-pixel tolerance. tools/render/regenerate_goldens.sh rewrites the goldens on purpose.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "render/headless_context.hpp"
#include "render/image.hpp"
#include "render/renderer.hpp"
#include "render/scenes.hpp"

namespace {

constexpr int kWidth = 480;
constexpr int kHeight = 270;
/// A channel may differ by this much (unit: 1/255) ...
constexpr int kTolerance = 6;
/// ... in at most this fraction of the pixels.
constexpr double kMaxFractionOver = 0.002;

class GoldenTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { context_ = std::make_unique<render::HeadlessContext>(); }
    static void TearDownTestSuite() { context_.reset(); }

    static render::Image draw(const render::DemoScene& scene, bool cache_table = true) {
        render::RenderSettings settings;
        settings.cache_table = cache_table;
        settings.look = scene.look;
        render::Renderer renderer(scene.table, scene.ball_radius, settings);
        render::OffscreenTarget target(kWidth, kHeight, 4);
        target.bind();
        renderer.draw(scene.frame(), kWidth, kHeight);
        target.resolve();
        return render::read_pixels(kWidth, kHeight);
    }

    static void check(const std::string& name, const render::Image& actual) {
        namespace fs = std::filesystem;
        const fs::path golden = fs::path(COOLAABER_TEST_DATA) / (name + ".png");
        const fs::path out_dir = fs::temp_directory_path() / "coolaaber-render";
        fs::create_directories(out_dir);
        const fs::path out = out_dir / (name + ".png");
        ASSERT_TRUE(render::write_png(out.string(), actual));
        const char* regen = std::getenv("COOLAABER_REGENERATE_GOLDENS");
        if (regen && std::string(regen) == "1") {
            ASSERT_TRUE(render::write_png(golden.string(), actual)) << "cannot write " << golden;
            return;
        }
        const render::Image expected = render::load_png(golden.string());
        ASSERT_GT(expected.width, 0)
            << "missing golden " << golden
            << ": run tools/render/regenerate_goldens.sh and look at the result";
        const render::ImageDiff d = render::compare(actual, expected, kTolerance);
        ASSERT_TRUE(d.same_size) << name << ": golden is " << expected.width << "x"
                                 << expected.height;
        EXPECT_LE(d.fraction_over, kMaxFractionOver)
            << name << ": " << d.fraction_over * 100 << "% of pixels differ by more than "
            << kTolerance << " (largest difference " << d.max_channel_diff
            << "); actual image: " << out
            << "; if the change is intended, run tools/render/regenerate_goldens.sh";
    }

    static std::unique_ptr<render::HeadlessContext> context_;
};

std::unique_ptr<render::HeadlessContext> GoldenTest::context_;

constexpr float kAspect = static_cast<float>(kWidth) / static_cast<float>(kHeight);

TEST_F(GoldenTest, RackedTableOverhead) {
    check("racked_overhead", draw(render::racked_scene(kAspect)));
}

TEST_F(GoldenTest, BallMidRoll) {
    check("mid_roll", draw(render::mid_roll_scene(kAspect)));
}

TEST_F(GoldenTest, MidGameOverhead) {
    check("mid_game", draw(render::mid_game_scene(kAspect)));
}

TEST_F(GoldenTest, CueBallViewWithAimGuide) {
    check("cue_view", draw(render::cue_view_scene(kAspect)));
}

TEST_F(GoldenTest, AimOverheadWithCueShadow) {
    check("aim_overhead", draw(render::aim_overhead_scene(kAspect)));
}

TEST_F(GoldenTest, BallShadowsOnTheCushion) {
    check("cushion", draw(render::cushion_scene(kAspect)));
}

TEST_F(GoldenTest, BallInHandAndTray) {
    check("ball_in_hand", draw(render::ball_in_hand_scene(kAspect)));
}

TEST_F(GoldenTest, CueBallViewAtARail) {
    check("rail_view", draw(render::rail_view_scene(kAspect)));
}

TEST_F(GoldenTest, RaisedCueFromAbove) {
    check("raised_cue", draw(render::raised_cue_scene(kAspect)));
}

TEST_F(GoldenTest, PocketWithADroppingBall) {
    check("pocket", draw(render::pocket_scene(kAspect)));
}

TEST_F(GoldenTest, RoomRoundTheTable) {
    check("room", draw(render::room_scene(kAspect)));
}

TEST_F(GoldenTest, AMovingCameraIsDrawnSmallerAndAStillOneInFull) {
    const render::DemoScene scene = render::cue_view_scene(kAspect);
    render::FrameView turned = scene.frame();
    turned.camera.eye.y += 0.05f;
    render::Renderer renderer(scene.table, scene.ball_radius);
    render::OffscreenTarget target(kWidth, kHeight, 4);
    auto frame = [&](const render::FrameView& v) {
        target.bind();
        renderer.draw(v, kWidth, kHeight);
        target.resolve();
        return render::read_pixels(kWidth, kHeight);
    };
    frame(scene.frame());
    const render::Image moving = frame(turned);  // the camera moved: drawn at 3/4 size
    const render::Image still = frame(turned);   // the same camera again: in full
    render::DemoScene turned_scene = scene;
    turned_scene.camera = turned.camera;
    const render::Image full = draw(turned_scene);
    EXPECT_EQ(render::compare(still, full, 0).max_channel_diff, 0);
    const render::ImageDiff d = render::compare(moving, full, 6);
    EXPECT_GT(d.fraction_over, 0.002);  // softer edges, no multisampling
    EXPECT_LT(d.fraction_over, 0.2);    // but the same picture
}

TEST_F(GoldenTest, RendersAreRepeatable) {
    const render::DemoScene scene = render::racked_scene(kAspect);
    const render::Image a = draw(scene), b = draw(scene);
    const render::ImageDiff d = render::compare(a, b, 0);
    EXPECT_EQ(d.max_channel_diff, 0);
}

TEST_F(GoldenTest, ExposureChangeReachesTheBakedCloth) {
    // The cloth's light is baked tone-mapped: a new exposure must re-bake it, and going back
    // must give the same frame again.
    const render::DemoScene scene = render::racked_scene(kAspect);
    render::Renderer renderer(scene.table, scene.ball_radius);
    render::OffscreenTarget target(kWidth, kHeight, 4);
    auto frame = [&]() {
        target.bind();
        renderer.draw(scene.frame(), kWidth, kHeight);
        target.resolve();
        return render::read_pixels(kWidth, kHeight);
    };
    const render::Image normal = frame();
    renderer.settings().exposure = 1.6f;
    const render::Image bright = frame();
    renderer.settings().exposure = 1.0f;
    const render::Image again = frame();
    // The middle of the cloth, green channel.
    const std::size_t centre =
        (static_cast<std::size_t>(kHeight / 2) * kWidth + kWidth / 3) * 4 + 1;
    EXPECT_GT(bright.rgba[centre], normal.rgba[centre] + 10);
    EXPECT_EQ(render::compare(normal, again, 0).max_channel_diff, 0);
}

TEST_F(GoldenTest, CachedTableMatchesDrawnTable) {
    const render::DemoScene scene = render::mid_game_scene(kAspect);
    const render::ImageDiff d = render::compare(draw(scene, true), draw(scene, false), 0);
    EXPECT_EQ(d.max_channel_diff, 0);
}

TEST_F(GoldenTest, SnookerTableOverhead) {
    check("snooker_overhead", draw(render::snooker_scene(kAspect)));
}

TEST_F(GoldenTest, SnookerCueBallView) {
    check("snooker_cue_view", draw(render::snooker_cue_view_scene(kAspect)));
}

TEST_F(GoldenTest, CaromTableOverhead) {
    check("carom_overhead", draw(render::carom_scene(kAspect)));
}

}  // namespace
