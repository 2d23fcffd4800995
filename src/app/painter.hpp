// Draws one frame of the game — the table view at the left, the panel at the right — into an
// offscreen multisampled target, which the window then shows (or a screenshot reads).
#pragma once

#include <memory>

#include "app/scene_frame.hpp"
#include "render/renderer.hpp"

struct ImDrawData;

namespace app {

class Painter {
  public:
    Painter(const physics::Table& table, double ball_radius);
    /// The window's size in pixels (the panel included).
    void resize(int width, int height);
    /// Draws the table into the view (width − panel) and the panel's draw data over it; leaves
    /// the resolved image bound for reading.
    void draw(const SceneFrame& scene, const render::Camera& camera, ImDrawData* panel);
    /// Copies the image to the window's framebuffer.
    void present() const;
    int width() const { return width_; }
    int height() const { return height_; }
    int view_width() const;

  private:
    render::Renderer renderer_;
    std::unique_ptr<render::OffscreenTarget> target_;
    int width_ = 0, height_ = 0;
};

}  // namespace app
