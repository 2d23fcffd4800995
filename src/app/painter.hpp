// Draws one frame of the game: the table view (multisampled, offscreen, the window less the
// panel, at its top left) and the panel over the rest, into the window or into an image.
#pragma once

#include <memory>

#include "app/panel_layout.hpp"
#include "app/scene_frame.hpp"
#include "render/image.hpp"
#include "render/renderer.hpp"

struct ImDrawData;

namespace app {

class Painter {
  public:
    /// `samples`: the still table view's multisampling (platform::Window::table_samples).
    Painter(const physics::Table& table, double ball_radius,
            render::GameLook look = render::GameLook::pool, int samples = 4);
    /// The window's size in pixels and the table view's (`view`, at the top left: the panel is
    /// at its right or below it).
    void resize(int width, int height, ViewSize view);
    /// Draws the table into the view. While the camera moves
    /// (`camera_moving`: aiming in the cue-ball view, a transition) the view is drawn without
    /// multisampling, which on a software renderer more than doubles the frame rate; a still
    /// camera gets `samples`× MSAA (and the renderer's cached table where it can).
    void draw_table(const SceneFrame& scene, const render::Camera& camera,
                    bool camera_moving = false);
    /// Shows the table view and the panel in the window's framebuffer (then swap).
    void show(ImDrawData* panel);
    /// The table view and the panel as an image (the offscreen screenshot).
    render::Image capture(ImDrawData* panel);
    int width() const { return width_; }
    int height() const { return height_; }
    int view_width() const { return view_size_.width; }
    int view_height() const { return view_size_.height; }

  private:
    /// Copies the table view into the bound draw framebuffer and draws the panel over it.
    void compose(unsigned table_image, ImDrawData* panel) const;

    render::Renderer renderer_;
    int samples_;
    std::unique_ptr<render::OffscreenTarget> view_;  ///< the table, multisampled
    std::unique_ptr<render::OffscreenTarget>
        moving_;  ///< the table while the camera moves, 1 sample
    std::unique_ptr<render::OffscreenTarget> picture_;  ///< capture(): the whole window
    int width_ = 0, height_ = 0;
    ViewSize view_size_;
};

}  // namespace app
