#include "app/painter.hpp"

#include <epoxy/gl.h>
#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>

#include "app/panel.hpp"

namespace app {

Painter::Painter(const physics::Table& table, double ball_radius) : renderer_(table, ball_radius) {}

void Painter::resize(int width, int height) {
    width = std::max(width, 64);
    height = std::max(height, 64);
    if (target_ && width == width_ && height == height_) return;
    width_ = width;
    height_ = height;
    target_ = std::make_unique<render::OffscreenTarget>(width_, height_, 4);
}

int Painter::view_width() const { return std::max(16, width_ - static_cast<int>(panel_width)); }

void Painter::draw(const SceneFrame& scene, const render::Camera& camera, ImDrawData* panel) {
    target_->bind();
    renderer_.draw(scene.view(camera), view_width(), height_);
    if (panel) {
        glViewport(0, 0, width_, height_);
        ImGui_ImplOpenGL3_RenderDrawData(panel);
    }
    target_->resolve();
}

void Painter::present() const {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

}  // namespace app
