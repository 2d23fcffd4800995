// The renderer: draws the table, the balls (ray-cast sphere impostors), their soft shadows,
// the cue and the aim guide into the current GL context's bound framebuffer, from a
// read-only view. OpenGL 3.3 core through libepoxy; no window code. Create it with a
// context current; it must be destroyed while that context is still current.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "physics/ball_state.hpp"
#include "physics/table.hpp"
#include "render/camera.hpp"
#include "render/textures.hpp"

namespace render {

/// One ball as drawn.
struct BallView {
    int id = 0;                         ///< 0 cue ball, 1–15 object balls
    glm::vec3 centre{0.0f};             ///< (unit: m), table frame; z = R on the cloth
    glm::quat orientation{1, 0, 0, 0};  ///< ball frame → table frame
};

/// The cue stick: where its tip is, which way it points, how far it is drawn back.
struct CueView {
    glm::vec2 cue_ball{0.0f};  ///< cue-ball centre (unit: m)
    float heading = 0.0f;      ///< direction of the stroke, from +x counter-clockwise (unit: rad)
    /// Butt raised by this angle (unit: rad); drawn at least at the elevation the rail forces
    /// (render::drawn_cue_elevation), which the stroke must use too.
    float elevation = 0.0f;
    float pull_back = 0.05f;  ///< gap between the tip and the ball (unit: m)
    /// Where the tip meets the ball: side (right of centre as the shooter sees it) and top
    /// (above centre), unit: R, as on the panel's tip picture (physics::Stroke side, top).
    glm::vec2 tip_offset{0.0f};
};

/// The aim guide: polylines on the cloth and a ghost ball, all from the physics engine.
/// A ring on the cloth (a disc when `half_width` ≥ `radius`): where the guide's path ends, the
/// called ball, the called pocket.
struct AimMark {
    glm::vec2 centre{0.0f};   ///< (unit: m), table frame
    float radius = 0.0f;      ///< (unit: m)
    float half_width = 0.0f;  ///< of the ring's line (unit: m)
    glm::vec3 colour{1.0f};
};

struct AimView {
    std::vector<glm::vec2> cue_path;     ///< cue ball to the first contact (unit: m)
    std::optional<glm::vec2> ghost;      ///< cue-ball centre at the first contact
    std::vector<glm::vec2> object_path;  ///< the object ball's direction after contact
    std::vector<glm::vec2> cue_after;    ///< the cue ball's direction after contact
    bool illegal = false;                ///< the shot as aimed is a foul: the guide is drawn red
    std::vector<AimMark> marks;
};

/// Ball-in-hand: the cue ball shown where the player would place it.
struct BallInHandView {
    glm::vec2 pos{0.0f};        ///< where the cue ball would go (unit: m), table frame
    bool legal = true;          ///< false: drawn tinted red (overlaps a ball, off the cloth, ...)
    bool kitchen_only = false;  ///< true: the area behind the head string (x < L/4) is shaded
    /// Snooker: the D is shaded (x of the baulk line, y of its centre, radius; unit: m).
    std::optional<glm::vec3> d_only;
};

/// Everything one frame shows. Spans must stay valid during draw().
struct FrameView {
    std::span<const BallView> balls;  ///< pocketed balls simply left out
    Camera camera;
    std::optional<CueView> cue;
    const AimView* aim = nullptr;
    /// The cue ball in hand: a semi-transparent ball and a ring at `pos`, red when not legal.
    std::optional<BallInHandView> ball_in_hand;
    /// Ids of the pocketed object balls, in the order they dropped: drawn in the ball-return
    /// tray along the table's south side (outside the rails), numbers up.
    std::span<const int> tray;
    /// The caller's word that the camera moves, or stopped only a moment ago and may move on
    /// (aiming): drawn as a moving camera (smaller, no table cache) even when it equals the
    /// last frame's, so that a pause between two mouse moves costs no full-quality frame.
    bool camera_moving = false;
};

/// Which game's balls and cloth marks are drawn: pool (numbered balls, head and foot spots),
/// snooker (15 reds and the six colours, plain; the baulk line, the D and the colour spots),
/// carom (white, yellow and red, plain; the UMB spots). Every table has diamonds on its rails.
enum class GameLook { pool, snooker, carom };

/// Quality switches (defaults: everything on).
struct RenderSettings {
    GameLook look = GameLook::pool;
    bool shadows = true;    ///< soft ball shadows and contact occlusion on the cloth
    bool fog = true;        ///< the table's lower part fades into the background
    float exposure = 1.0f;  ///< scale of all light (unit: 1)
    /// Draw the table once per camera and size into a cache and copy it each frame (the
    /// overhead camera is fixed). Used only when the bound framebuffer is an FBO with a
    /// 24-bit depth attachment (OffscreenTarget); otherwise the table is drawn every frame.
    bool cache_table = true;
    /// While the camera moves (it differs from the previous frame's: aiming in the cue-ball
    /// view, a transition), the frame is drawn at this fraction of the size, without the table
    /// cache, and scaled up (bilinear) into the bound framebuffer's colour; a still camera is
    /// drawn at full size. 1: always full size.
    float moving_scale = 0.75f;
    /// While moving frames take longer than moving_budget_ms to draw, their scale steps down
    /// (by 1/16) to at most this; it steps back up toward moving_scale while they take well
    /// under it (MovingScale). A moving frame ends with glFinish so that its cost is known.
    /// Equal to moving_scale (or more): the scale stays fixed.
    float moving_scale_lowest = 0.5f;
    double moving_budget_ms = 22.0;  ///< (unit: ms) leaves a 30 fps frame room for the rest
    /// TrueType font the ball numbers are rasterized from at start-up; the Renderer's
    /// constructor throws std::runtime_error when it is missing.
    std::string number_font = kDefaultNumberFont;
};

/// Standard ball colours (sRGB, 0–1): 0 cue ball, 1–8 solids, 9–15 stripes of 1–7's colour.
glm::vec3 ball_colour(int id);
bool is_stripe(int id);
/// A ball's colour in a game's set (sRGB): pool as ball_colour; snooker 0 white, 1–15 red,
/// 16 yellow … 21 black; carom 0 white, 1 yellow, 2 red.
glm::vec3 ball_colour(int id, GameLook look);

/// A ball on the cloth from a physics state (z = R).
BallView ball_view(const physics::BallState& state, double ball_radius,
                   const glm::dquat& orientation);

class OffscreenTarget;

class Renderer {
  public:
    Renderer(const physics::Table& table, double ball_radius, RenderSettings settings = {});
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /// Clears and draws a frame into the bound framebuffer's (0, 0, width, height) viewport.
    void draw(const FrameView& frame, int width, int height);
    /// The same into `target`, which it binds; the table cache then asks the GL nothing about
    /// the framebuffer (under WebGL each such question waits for the GPU process to catch up).
    void draw(const FrameView& frame, OffscreenTarget& target);

    /// The scale the next moving frame is drawn at (RenderSettings::moving_scale_lowest).
    float moving_scale() const;
    RenderSettings& settings();

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// An offscreen target: a multisampled framebuffer (when `samples` > 1 and supported),
/// resolved into a plain RGBA8 one that read_pixels() can read.
class OffscreenTarget {
  public:
    OffscreenTarget(int width, int height, int samples = 4);
    ~OffscreenTarget();
    OffscreenTarget(const OffscreenTarget&) = delete;
    OffscreenTarget& operator=(const OffscreenTarget&) = delete;
    /// Binds the framebuffer to draw into.
    void bind();
    /// Resolves the samples and binds the result for reading (one sample: binds the image
    /// drawn, no copy).
    void resolve();
    int width() const { return width_; }
    int height() const { return height_; }
    int samples() const { return samples_; }

  private:
    int width_, height_, samples_;
    unsigned draw_fbo_ = 0, draw_colour_ = 0, draw_depth_ = 0;
    unsigned resolve_fbo_ = 0, resolve_colour_ = 0;
};

}  // namespace render
