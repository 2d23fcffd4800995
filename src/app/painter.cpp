#include "app/painter.hpp"

#include <backends/imgui_impl_opengl3.h>
#include <epoxy/gl.h>
#include <imgui.h>

#include <algorithm>

namespace app {

namespace {

render::RenderSettings with_look(render::GameLook look) {
    render::RenderSettings s;
    s.look = look;
    return s;
}

}  // namespace

Painter::Painter(const physics::Table& table, double ball_radius, render::GameLook look,
                 int samples)
    : renderer_(table, ball_radius, with_look(look)), samples_(samples) {}

void Painter::resize(int width, int height, ViewSize view) {
    width = std::max(width, 64);
    height = std::max(height, 64);
    view = {std::clamp(view.width, 16, width), std::clamp(view.height, 16, height)};
    if (view_ && width == width_ && height == height_ && view.width == view_size_.width &&
        view.height == view_size_.height)
        return;
    width_ = width;
    height_ = height;
    view_size_ = view;
    view_ = std::make_unique<render::OffscreenTarget>(view_width(), view_height(), samples_);
    moving_.reset();
    picture_.reset();
}

void Painter::draw_table(const SceneFrame& scene, const render::Camera& camera,
                         bool camera_moving) {
    if (camera_moving && !moving_)
        moving_ = std::make_unique<render::OffscreenTarget>(view_width(), view_height(), 1);
    render::OffscreenTarget& target = camera_moving ? *moving_ : *view_;
    render::FrameView view = scene.view(camera);
    view.camera_moving = camera_moving;
    renderer_.draw(view, target);
    target.resolve();  // leaves the resolved table image bound for reading
}

void Painter::compose(unsigned table_image, ImDrawData* panel) const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, table_image);
    glDisable(GL_SCISSOR_TEST);
    glViewport(0, 0, width_, height_);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    // GL counts rows from the bottom: the view's top left is the window's.
    glBlitFramebuffer(0, 0, view_width(), view_height(), 0, height_ - view_height(), view_width(),
                      height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    if (panel) ImGui_ImplOpenGL3_RenderDrawData(panel);
}

void Painter::show(ImDrawData* panel) {
    GLint table_image = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &table_image);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    compose(static_cast<unsigned>(table_image), panel);
}

render::Image Painter::capture(ImDrawData* panel) {
    GLint table_image = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &table_image);
    if (!picture_) picture_ = std::make_unique<render::OffscreenTarget>(width_, height_, 1);
    picture_->bind();
    compose(static_cast<unsigned>(table_image), panel);
    picture_->resolve();
    return render::read_pixels(width_, height_);
}

}  // namespace app
