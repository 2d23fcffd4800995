// The window's game loop (platform.hpp: SDL2 on the desktop, the browser on the web): events →
// input → update → draw, in one frame at a time, drawing only when something changed.
#include "app/app.hpp"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <tuple>

#include "app/controller.hpp"
#include "app/game_setup.hpp"
#include "app/imgui_setup.hpp"
#include "app/input.hpp"
#include "app/painter.hpp"
#include "app/panel.hpp"
#include "app/panel_layout.hpp"
#include "app/picking.hpp"
#include "app/platform.hpp"
#include "app/scene_frame.hpp"
#include "app/status_report.hpp"
#include "app/table.hpp"
#include "audio/engine.hpp"

namespace app {

namespace {

audio::Listener listener_of(const render::Camera& c) {
    const glm::vec3 f = c.target - c.eye;
    return {{c.eye.x, c.eye.y, c.eye.z}, {f.x, f.y, f.z}, {c.up.x, c.up.y, c.up.z}};
}

// The game in a window: init (the constructor), one frame at a time, shutdown (the destructor).
class WindowLoop {
  public:
    WindowLoop(GameSetup setup, std::unique_ptr<platform::Window> window,
               const std::optional<std::filesystem::path>& status_file);
    ~WindowLoop();
    WindowLoop(const WindowLoop&) = delete;
    WindowLoop& operator=(const WindowLoop&) = delete;

    /// Handles the events, updates, and draws when something changed; false once the player
    /// has asked to exit.
    bool frame();

  private:
    bool animating() const;
    /// The camera has been still long enough for a full-quality frame: aiming, the mouse
    /// pauses between moves, and a full frame at each pause would halve the rate.
    bool settled() const {
        return std::chrono::steady_clock::now() - last_motion_ >= std::chrono::milliseconds(200);
    }
    bool handle_events();
    /// The mouse is over the table view (the top left of the window), not the panel.
    bool over_table() const {
        return mouse_x_ < painter_->view_width() && mouse_y_ < painter_->view_height();
    }
    void on_event(const platform::Event& e);
    bool update();
    void draw();
    void write_status(const SceneFrame& scene, int w, int h, const PanelLayout& layout);
    void keep_saved();
    PanelLayout scaled_panel_layout(int w, int h) const;
    void paint_the_session_table();

    std::unique_ptr<platform::Window> window_;
    Table t_;
    audio::Engine sound_;  // no device: silent, one line on stderr
    std::optional<Painter> painter_;
    std::string painted_;  // the table the painter draws (a pasted link may bring another)
    float ui_scale_ = 1.0f;
    std::optional<StatusFile> status_;
    TableInput input_;
    double mouse_x_ = 0, mouse_y_ = 0;
    bool mouse_down_[3] = {false, false, false};
    bool mouse_pressed_[3] = {false, false, false};  // a press this frame, even if released again
    int sound_serial_;
    int warm_frames_ = 2;
    bool drew_moving_ = false;  // the last frame was drawn for a moving camera (smaller, 1×)
    std::chrono::steady_clock::time_point last_motion_ = std::chrono::steady_clock::now();
    long frames_ = 0;
    std::pair<int, int> saved_at_;  // the shot and game last saved (saves_as_it_goes)
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

WindowLoop::WindowLoop(GameSetup setup, std::unique_ptr<platform::Window> window,
                       const std::optional<std::filesystem::path>& status_file)
    : window_(std::move(window)),
      t_(std::move(setup)),
      input_(t_.controller, t_.rig,
             [this](double x, double y) {
                 const double R = t_.controller.session().config().params.ball_radius;
                 return table_point(t_.last_camera, painter_->view_width(), painter_->view_height(),
                                    x, y, R);
             }),
      sound_serial_(t_.controller.shot_serial()),
      saved_at_(t_.controller.shot_serial(), t_.controller.session().game_number()) {
    create_imgui();
    window_->start_imgui();
    sound_.set_muted(!t_.setup.settings.sound);
    paint_the_session_table();
    ui_scale_ = dpi_scale(std::getenv("COOLAABER_UI_SCALE"), window_->dpi());
    input_.sensitivity.normal /= window_->pixels_per_point();
    input_.sensitivity.fine /= window_->pixels_per_point();
    if (status_file) status_.emplace(*status_file);
}

WindowLoop::~WindowLoop() {
    t_.save_and_close();
    painter_.reset();  // its GL objects go while the context lives
    window_->stop_imgui();
    destroy_imgui();
}

void WindowLoop::paint_the_session_table() {
    if (table_key(t_.controller) == painted_) return;
    painted_ = table_key(t_.controller);
    painter_.emplace(t_.controller.session().table(),
                     t_.controller.session().config().params.ball_radius, t_.controller.look(),
                     window_->table_samples());
}

// A camera that has just stopped gets one more frame, drawn in full.
bool WindowLoop::animating() const {
    const Controller& c = t_.controller;
    return c.moving() || t_.rig.animating() || warm_frames_ > 0 || (drew_moving_ && settled()) ||
           (c.busy() && !c.computer_thinking());
}

bool WindowLoop::frame() {
    const bool had_event = handle_events();
    if (t_.exit_requested) return false;
    const bool changed = update();
    if (had_event || changed) draw();
    keep_saved();
    return !t_.exit_requested;
}

// Where the game has no exit to save on, it is saved each time the balls come to rest.
void WindowLoop::keep_saved() {
    if (!window_->saves_as_it_goes() || t_.controller.moving()) return;
    const std::pair<int, int> now(t_.controller.shot_serial(),
                                  t_.controller.session().game_number());
    if (now == saved_at_) return;
    saved_at_ = now;
    const std::string err = t_.save_game();
    if (!err.empty()) {
        t_.panel.notice = "The game could not be saved: " + err;
        t_.panel.notice_is_error = true;
    }
    window_->files_written();
}

// Waits for an event when nothing moves; true when there was one.
bool WindowLoop::handle_events() {
    const bool was_animating = animating();
    const int wait_ms = was_animating                                           ? 0
                        : t_.controller.computer_thinking() || sound_.pending() ? 30
                        : drew_moving_                                          ? 20
                                                                                : 500;
    const std::vector<platform::Event> events = window_->events(wait_ms);
    for (const platform::Event& e : events) on_event(e);
    warm_frames_ = !events.empty() ? 3 : std::max(0, warm_frames_ - 1);
    return !events.empty() || was_animating;
}

void WindowLoop::on_event(const platform::Event& e) {
    using Kind = platform::Event::Kind;
    const bool ui = ImGui::GetIO().WantCaptureMouse;
    const bool over_panel = !over_table();
    switch (e.kind) {
        case Kind::quit:
            t_.exit_requested = true;
            return;
        case Kind::motion:
            mouse_x_ = e.x;
            mouse_y_ = e.y;
            return input_.motion(mouse_x_, mouse_y_, window_->shift_held());
        case Kind::button: {
            mouse_x_ = e.x;
            mouse_y_ = e.y;
            const int slot = std::clamp(e.button, 0, 2);
            mouse_down_[slot] = e.down;
            if (e.down) mouse_pressed_[slot] = true;
            const MouseButton b = slot == 0   ? MouseButton::left
                                  : slot == 1 ? MouseButton::right
                                              : MouseButton::middle;
            if (e.down && !ui && over_table()) input_.press(b, e.x, e.y);
            if (!e.down) input_.release(b, e.x, e.y);
            return;
        }
        case Kind::wheel:
            if (!over_panel) input_.wheel(e.wheel);
            return;
        case Kind::key:
            // Not while a dialog is open: its buttons answer it, the table waits.
            if (!ImGui::GetIO().WantTextInput &&
                !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId))
                on_key(t_, *window_, e);
            return;
        case Kind::resized:
            t_.setup.settings.window_width = e.width;
            t_.setup.settings.window_height = e.height;
            return;
        case Kind::link:
            return t_.open_link(e.text, Table::LinkFrom::address);
        case Kind::other:
            return;
    }
}

// Advances the game and the sound; true when what the player sees changed.
bool WindowLoop::update() {
    const auto now = std::chrono::steady_clock::now();
    const double dt = std::min(0.1, std::chrono::duration<double>(now - last_).count());
    last_ = now;
    Controller& c = t_.controller;
    auto signature = [&] {
        return std::tuple(c.shot_serial(), c.busy(), c.computer_thinking(), c.session().phase(),
                          c.session().game_number());
    };
    const auto before = signature();
    c.update(dt);
    t_.rig.update(dt);
    t_.follow_cue_ball();
    if (c.shot_serial() != sound_serial_) {
        sound_serial_ = c.shot_serial();
        if (c.moving()) sound_.start(c.playback().shot());
    }
    sound_.set_muted(!t_.setup.settings.sound);
    if (c.moving() && c.playback().time() >= 0.0)
        sound_.update(c.playback().time());
    else if (!c.moving())
        sound_.advance(dt);  // a potted ball still runs to the return
    return signature() != before || (drew_moving_ && settled());
}

// The panel laid out in the mouse's units (CSS pixels on the web), then scaled to the drawable.
PanelLayout WindowLoop::scaled_panel_layout(int w, int h) const {
    const double ppp = window_->pixels_per_point();
    PanelLayout layout = panel_layout(static_cast<int>(std::lround(w / ppp)),
                                      static_cast<int>(std::lround(h / ppp)), ui_scale_);
    layout.width = std::round(layout.width * static_cast<float>(ppp));
    layout.height = std::round(layout.height * static_cast<float>(ppp));
    layout.scale *= static_cast<float>(ppp);
    return layout;
}

void WindowLoop::draw() {
    const auto [w, h] = window_->drawable_size();
    const PanelLayout layout = scaled_panel_layout(w, h);
    paint_the_session_table();
    painter_->resize(w, h, table_view(layout, w, h));
    set_ui_scale(layout.scale);
    window_->new_imgui_frame();
    // ImGui 1.86's SDL backend reads the global mouse state, stale under Xvfb/XTEST: the
    // position and buttons come from the events instead.
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(static_cast<float>(mouse_x_), static_cast<float>(mouse_y_));
    for (int i = 0; i < 3; ++i) {
        io.MouseDown[i] = mouse_down_[i] || mouse_pressed_[i];
        mouse_pressed_[i] = false;
    }
    ImGui::NewFrame();
    const PanelActions actions = draw_panel(t_.controller, t_.setup.settings, t_.panel,
                                            static_cast<float>(w), static_cast<float>(h), layout);
    ImGui::Render();
    t_.apply(actions, window_.get());
    if (!mouse_down_[0] && !mouse_down_[1] && !mouse_down_[2] && !(t_.setup.settings == t_.saved)) {
        t_.persist_settings();  // not mid-drag
        window_->files_written();
    }
    const float aspect =
        static_cast<float>(painter_->view_width()) / static_cast<float>(painter_->view_height());
    const render::Camera previous = t_.last_camera;
    t_.last_camera = t_.camera(aspect);
    bool camera_moving = t_.rig.animating() || previous.eye != t_.last_camera.eye ||
                         previous.target != t_.last_camera.target;
    if (camera_moving) last_motion_ = std::chrono::steady_clock::now();
    camera_moving = camera_moving || (drew_moving_ && !settled());
    drew_moving_ = camera_moving;
    sound_.set_listener(listener_of(t_.last_camera));
    const SceneFrame scene =
        build_scene(t_.controller, t_.setup.settings.aim_guide, input_.dragged_to());
    painter_->draw_table(scene, t_.last_camera, camera_moving);
    painter_->show(ImGui::GetDrawData());
    window_->present();
    ++frames_;
    write_status(scene, w, h, layout);
}

void WindowLoop::write_status(const SceneFrame& scene, int w, int h, const PanelLayout& layout) {
    if (!status_) return;
    status_->write(status_json(t_.controller, t_.setup.settings, t_.rig.mode(),
                               {t_.panel.widgets,
                                frames_,
                                scene.cue.has_value(),
                                scene.show_aim,
                                scene.ball_in_hand.has_value(),
                                static_cast<int>(scene.aim.marks.size()),
                                scene.show_aim && scene.aim.illegal,
                                {w, h},
                                static_cast<int>(layout.width),
                                static_cast<int>(layout.height),
                                {painter_->view_width(), painter_->view_height()},
                                t_.link_note_shown(),
                                ball_pixels(t_, painter_->view_width(), painter_->view_height())}));
}

}  // namespace

int run_window(const AppOptions& options) {
    std::optional<GameSetup> setup = set_up_or_report(options);
    if (!setup) return 2;
    std::string why;
    std::unique_ptr<platform::Window> window =
        platform::Window::open(setup->settings.window_width, setup->settings.window_height,
                               setup->settings.fullscreen, why);
    if (!window) {
        std::fprintf(stderr, "coolaaber: %s\n", why.c_str());
        return 1;
    }
    // The loop outlives this call on the web (the browser calls its frames).
    auto loop =
        std::make_shared<WindowLoop>(std::move(*setup), std::move(window), options.status_file);
    platform::run([loop]() mutable {
        if (!loop) return false;
        if (loop->frame()) return true;
        loop.reset();  // saves the game and settings, closes the window
        return false;
    });
    return 0;
}

}  // namespace app
