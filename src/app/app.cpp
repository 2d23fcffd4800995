// The window's main loop (SDL2 + Dear ImGui): events → input → update → draw, waiting for
// events when nothing moves; and the offscreen screenshot (EGL, no window).
#include "app/app.hpp"

#include <SDL.h>
#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>
#include <epoxy/gl.h>
#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <stdexcept>
#include <tuple>

#include "app/camera_rig.hpp"
#include "app/controller.hpp"
#include "app/display.hpp"
#include "app/game_setup.hpp"
#include "app/imgui_setup.hpp"
#include "app/input.hpp"
#include "app/match_setup.hpp"
#include "app/painter.hpp"
#include "app/panel.hpp"
#include "app/panel_layout.hpp"
#include "app/picking.hpp"
#include "app/scene_frame.hpp"
#include "app/seats.hpp"
#include "app/shot_sharing.hpp"
#include "app/status_report.hpp"
#include "audio/engine.hpp"
#include "game/atomic_file.hpp"
#include "game/json_field.hpp"
#include "game/state_json.hpp"
#include "game/text_file.hpp"
#include "render/headless_context.hpp"
#include "render/image.hpp"

namespace app {

namespace {

CameraMode camera_mode(ViewMode v) {
    return v == ViewMode::overhead ? CameraMode::overhead : CameraMode::cue_ball;
}

audio::Listener listener_of(const render::Camera& c) {
    const glm::vec3 f = c.target - c.eye;
    return {{c.eye.x, c.eye.y, c.eye.z}, {f.x, f.y, f.z}, {c.up.x, c.up.y, c.up.z}};
}

glm::vec2 cue_ball_at(const Controller& c) {
    for (const physics::BallState& b : c.balls_now())
        if (b.id == c.cue_ball_id())
            return {static_cast<float>(b.pos.x), static_cast<float>(b.pos.y)};
    const physics::Vec2 h = c.session().table().head_spot();
    return {static_cast<float>(h.x), static_cast<float>(h.y)};
}

// The game: a controller and its camera, the panel's state and the settings, as one window
// or one screenshot shows them.
struct Table {
    GameSetup setup;
    Controller controller;
    CameraRig rig;
    PanelState panel;
    render::Camera last_camera;
    Settings saved;  ///< the settings as last written
    bool exit_requested = false;

    explicit Table(GameSetup s)
        : setup(std::move(s)),
          controller(std::move(*setup.session), setup.controller),
          rig(camera_mode(setup.settings.view)) {
        panel.notice = setup.notice;
        panel.notice_is_error = setup.notice_is_error;
        saved = setup.settings;
        controller.set_power(setup.settings.power);
        if (setup.practice) start_practice(setup.settings.game);
        if (setup.shared_stroke) {
            controller.play_shared(*setup.shared_stroke);
            note_link(
                "Opened a shot link: the shot plays as it was shared; Replay (P) shows it "
                "again, or play on from where it leaves the balls.",
                false);
        }
    }

    std::string link_note_shown() const {
        return panel.link_note_serial == controller.shot_serial() ? panel.link_note : "";
    }

    /// A line about a shot link in the information bar, until the next shot.
    void note_link(std::string text, bool is_error) {
        panel.link_note = std::move(text);
        panel.link_note_is_error = is_error;
        panel.link_note_serial = controller.shot_serial();
    }

    /// Copy shot link: the last shot (or the shot as aimed) as link text on the clipboard.
    void copy_link() {
        const ShotToShare s =
            shot_to_share(controller.session(), controller.stroke_of(controller.aim()));
        if (!s.shot) return note_link(s.why_not, true);
        if (SDL_SetClipboardText(game::shot_link(*s.shot).c_str()) != 0)
            return note_link(std::string("The clipboard could not be written: ") + SDL_GetError(),
                             true);
        note_link(copied_notice(*s.shot, !controller.session().history().empty()), false);
    }

    /// Opens a pasted shot link: its position and table, and its stroke played at once. A bad
    /// link is reported and the game is left as it was.
    void open_link(const std::string& text) {
        game::SharedShot shot;
        try {
            shot = game::read_shot_link(text);
        } catch (const game::LoadError& e) {
            return note_link(
                std::string("The pasted text is not a shot link this game can open: ") + e.what(),
                true);
        }
        ControllerOptions opts = setup.controller;
        opts.players = setup.settings.players;
        opts.seed = fresh_seed();
        controller.replace(
            session_of(shot, seat_names(setup.settings.names, opts.players), opts.seed), opts);
        controller.play_shared(shot.stroke);
        note_link("Opened the pasted shot link: Replay (P) shows it again, or play on.", false);
    }

    void start_practice(rules::Game game) {
        ControllerOptions opts = setup.controller;
        opts.seed = fresh_seed();
        controller.start_practice(
            game::Practice(game, physics::TableSpec{}, physics::Params{}, opts.seed), opts);
    }

    /// Save position: the practice position as coolaaber-cli simulate's input.
    void save_position() {
        try {
            std::error_code ec;
            std::filesystem::create_directories(setup.position_path.parent_path(), ec);
            game::write_file_atomically(setup.position_path, controller.practice()->to_json());
            note_link("Saved the position to " + setup.position_path.string() +
                          " (coolaaber-cli simulate reads it).",
                      false);
        } catch (const std::exception& e) {
            note_link(std::string("The position was not saved: ") + e.what(), true);
        }
    }

    /// Load position: the position saved last, or why it cannot be read (nothing changes).
    void load_position() {
        try {
            game::Practice p =
                game::Practice::from_json(game::read_regular_file(setup.position_path));
            ControllerOptions opts = setup.controller;
            opts.seed = fresh_seed();
            controller.start_practice(std::move(p), opts);
            note_link("Loaded the position from " + setup.position_path.string() + ".", false);
        } catch (const game::LoadError& e) {
            note_link(std::string("The position could not be loaded: ") + e.what(), true);
        }
    }

    void paste_link() {
        char* text = SDL_GetClipboardText();
        const std::string pasted = text ? text : "";
        SDL_free(text);
        if (pasted.empty())
            return note_link("The clipboard is empty: copy a shot link first.", true);
        open_link(pasted);
    }

    render::Camera camera(float aspect) const {
        return rig.camera(controller.session().table(), aspect);
    }

    // Keeps the cue-ball view on the cue ball and the aim (frozen while the balls move).
    void follow_cue_ball() {
        if (controller.moving()) return;
        const float heading =
            static_cast<float>(controller.aim().heading_deg * std::numbers::pi / 180.0);
        const float elevation =
            static_cast<float>(controller.aim().elevation_deg * std::numbers::pi / 180.0);
        rig.set_anchor(cue_ball_at(controller), heading, true, last_camera, elevation);
    }

    void set_power(double power) {
        controller.set_power(power);
        setup.settings.power = std::clamp(power, 0.0, 1.0);
    }

    void change_view() {
        rig.next_view(last_camera);
        setup.settings.view =
            rig.mode() == CameraMode::cue_ball ? ViewMode::cue_ball : ViewMode::overhead;
    }

    void apply(const PanelActions& a) {
        Settings& s = setup.settings;
        if (a.power) set_power(*a.power);
        if (a.sound) s.sound = *a.sound;
        if (a.aim_guide) s.aim_guide = *a.aim_guide;
        if (a.change_view) change_view();
        if (a.restart) controller.restart();
        if (a.exit) exit_requested = true;
        if (a.skip) controller.skip();
        if (a.replay) controller.replay();
        if (a.strike) controller.strike();
        if (a.hint) controller.hint();
        if (a.copy_link) copy_link();
        if (a.try_again) controller.try_again();
        if (a.save_position && controller.practicing()) save_position();
        if (a.load_position) load_position();
        if (a.spin) controller.set_spin(a.spin->first, a.spin->second);
        if (a.elevation_deg) controller.set_elevation(*a.elevation_deg);
        if (a.choice) controller.choose(*a.choice);
        if (a.push_out) controller.set_push_out(*a.push_out);
        if (a.call_safety) controller.call_safety();
        if (a.clear_call) controller.clear_call();
        if (a.after_foul) controller.choose_after_foul(*a.after_foul);
        if (a.nominate) controller.nominate(*a.nominate);
        if (a.next_frame) controller.next_frame();
        if (a.new_game) {
            s.game = a.new_game->game;
            s.names = a.new_game->names;
            s.players = a.new_game->players;
            s.house_rules = a.new_game->house_rules;
            s.aim_guide = a.new_game->aim_guide;
            ControllerOptions opts = setup.controller;
            opts.players = s.players;
            opts.seed = fresh_seed();
            try {
                if (a.new_game->table != TableGame::pool)
                    return start_match(controller, *a.new_game, opts);
                if (a.new_game->practice) return start_practice(s.game);
                controller.replace(game::Session(new_game_config(s, opts.seed)), opts);
            } catch (const std::exception& e) {
                panel.notice = e.what();
                panel.notice_is_error = true;
            }
        }
    }

    /// Writes the settings when they changed (the Sound checkbox, the power, the view...), so
    /// they persist at once and not only on Exit.
    void persist_settings() {
        if (setup.settings == saved || setup.settings_path.empty()) return;
        try {
            save_settings(setup.settings_path, setup.settings);
            saved = setup.settings;
        } catch (const std::exception& e) {
            panel.notice = std::string("The settings could not be saved: ") + e.what();
            panel.notice_is_error = true;
            saved = setup.settings;  // say it once
        }
    }

    void save_and_close() {
        // Practice is not a game, and a snooker or three-cushion match is not saved on exit:
        // the pool game saved before either stays as it was.
        const bool pool_game =
            !controller.practicing() && !controller.snooker() && !controller.carom();
        const std::string err =
            !pool_game ? std::string() : save_on_exit(controller.session(), setup.autosave_path);
        if (!err.empty())
            std::fprintf(stderr, "coolaaber: the game was not saved: %s\n", err.c_str());
        if (setup.settings_path.empty()) return;
        try {
            save_settings(setup.settings_path, setup.settings);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "coolaaber: the settings were not saved: %s\n", e.what());
        }
    }
};

// What the painter's table is built from.
std::string table_key(const Controller& c) {
    const game::Session& s = c.session();
    return game::to_json(s.config().table).dump() +
           fmt::format("{} {}", s.config().params.ball_radius, static_cast<int>(c.look()));
}

// Where each ball is seen in the table view (the status file's test hook).
std::map<int, std::array<double, 2>> ball_pixels(const Table& t, int width, int height) {
    std::map<int, std::array<double, 2>> out;
    const double R = t.controller.session().config().params.ball_radius;
    for (const physics::BallState& b : t.controller.balls_now())
        if (auto px = screen_point(t.last_camera, width, height, b.pos, R)) out[b.id] = *px;
    return out;
}

bool key_shift() {
    return (SDL_GetModState() & KMOD_SHIFT) != 0;
}

// The keyboard at the table (docs/app.md, "Playing").
void on_key(Table& t, SDL_Window* window, SDL_Keycode key, Uint16 mod) {
    const bool shift = (mod & KMOD_SHIFT) != 0;
    switch (key) {
        case SDLK_LEFT:
            t.controller.turn_aim(shift ? 0.05 : 0.5);
            break;
        case SDLK_RIGHT:
            t.controller.turn_aim(shift ? -0.05 : -0.5);
            break;
        case SDLK_UP:
            t.set_power(t.controller.aim().power + 0.05);
            break;
        case SDLK_DOWN:
            t.set_power(t.controller.aim().power - 0.05);
            break;
        case SDLK_SPACE:
            t.controller.strike();
            break;
        case SDLK_v:
            if ((mod & KMOD_CTRL) != 0)
                t.paste_link();
            else
                t.change_view();
            break;
        case SDLK_s:
        case SDLK_RETURN:
            t.controller.skip();
            break;
        case SDLK_p:
            t.controller.replay();
            break;
        case SDLK_h:
            t.controller.hint();
            break;
        case SDLK_g:
            t.setup.settings.aim_guide = next_aim_guide(t.setup.settings.aim_guide);
            break;
        case SDLK_o:
            t.rig.set_mode(
                t.rig.mode() == CameraMode::free ? CameraMode::overhead : CameraMode::free,
                t.last_camera);
            break;
        case SDLK_r:
            t.panel.confirm_restart = true;
            break;
        case SDLK_ESCAPE:
            t.panel.menu = true;
            break;
        case SDLK_F11: {
            const bool full = (SDL_GetWindowFlags(window) & SDL_WINDOW_FULLSCREEN_DESKTOP) != 0;
            SDL_SetWindowFullscreen(window, full ? 0 : SDL_WINDOW_FULLSCREEN_DESKTOP);
            t.setup.settings.fullscreen = !full;
            break;
        }
        default:
            break;
    }
}

// The game to start, or empty (the reason on stderr) when a --load file is bad.
std::optional<GameSetup> set_up_or_report(const AppOptions& options) {
    try {
        return set_up_game(options);
    } catch (const game::LoadError& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return std::nullopt;
    }
}

}  // namespace

int run_window(const AppOptions& options) {
    std::optional<GameSetup> setup = set_up_or_report(options);
    if (!setup) return 2;
    if (const std::optional<std::string> why = open_video()) {
        std::fprintf(stderr, "coolaaber: %s\n", why->c_str());
        return 1;
    }
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    const Settings& s0 = setup->settings;
    Uint32 flags = SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE;
    if (s0.fullscreen) flags |= SDL_WINDOW_FULLSCREEN_DESKTOP;
    SDL_Window* window =
        SDL_CreateWindow("Coolaaber", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                         s0.window_width, s0.window_height, flags);
    if (!window) {
        std::fprintf(stderr, "coolaaber: cannot open a window: %s\n", SDL_GetError());
        SDL_Quit();
        return 1;
    }
    SDL_GLContext gl = SDL_GL_CreateContext(window);
    if (!gl || epoxy_gl_version() < 33) {
        std::fprintf(
            stderr,
            "coolaaber: OpenGL 3.3 is needed, but this display offers %s (%s). Update the graphics "
            "driver, or run with Mesa's software renderer (LIBGL_ALWAYS_SOFTWARE=1).\n",
            gl ? reinterpret_cast<const char*>(glGetString(GL_VERSION)) : "none", SDL_GetError());
        if (gl) SDL_GL_DeleteContext(gl);
        SDL_DestroyWindow(window);
        SDL_Quit();
        return 1;
    }
    SDL_GL_MakeCurrent(window, gl);
    SDL_GL_SetSwapInterval(1);

    {
        Table t(std::move(*setup));
        create_imgui();
        ImGui_ImplSDL2_InitForOpenGL(window, gl);
        ImGui_ImplOpenGL3_Init("#version 330 core");
        audio::Engine sound;  // no device: silent, one line on stderr
        sound.set_muted(!t.setup.settings.sound);
        std::optional<Painter> painter;
        std::string painted;  // the table the painter draws (a pasted link may bring another)
        auto paint_the_session_table = [&] {
            if (table_key(t.controller) == painted) return;
            painted = table_key(t.controller);
            painter.emplace(t.controller.session().table(),
                            t.controller.session().config().params.ball_radius,
                            t.controller.look());
        };
        paint_the_session_table();
        float dpi = 0.0f;
        if (SDL_GetDisplayDPI(0, nullptr, &dpi, nullptr) != 0) dpi = 0.0f;
        const float ui_scale = dpi_scale(std::getenv("COOLAABER_UI_SCALE"), dpi);
        std::optional<StatusFile> status;
        if (options.status_file) status.emplace(*options.status_file);

        auto to_table = [&](double x, double y) {
            const double R = t.controller.session().config().params.ball_radius;
            return table_point(t.last_camera, painter->view_width(), painter->height(), x, y, R);
        };
        TableInput input(t.controller, t.rig, to_table);
        double mouse_x = 0, mouse_y = 0;
        bool mouse_down[3] = {false, false, false};
        bool mouse_pressed[3] = {false, false,
                                 false};  // a press this frame, even if released again
        int sound_serial = t.controller.shot_serial();
        int warm_frames = 2;
        bool drew_moving = false;  // the last frame was drawn for a moving camera (smaller, 1×)
        // The full-quality frame waits until the camera has been still this long: aiming, the
        // mouse pauses between moves, and a full frame at each pause would halve the rate.
        const auto settle = std::chrono::milliseconds(200);
        auto last_motion = std::chrono::steady_clock::now();
        auto settled = [&] { return std::chrono::steady_clock::now() - last_motion >= settle; };
        long frames = 0;
        auto last = std::chrono::steady_clock::now();
        auto over_panel = [&](double x) { return x >= painter->view_width(); };

        while (!t.exit_requested) {
            // ---- Events: wait for one when nothing moves
            // A camera that has just stopped gets one more frame, drawn in full.
            const bool animating = t.controller.moving() || t.rig.animating() || warm_frames > 0 ||
                                   (drew_moving && settled()) ||
                                   (t.controller.busy() && !t.controller.computer_thinking());
            SDL_Event e;
            bool have = false;
            if (!animating)
                have = SDL_WaitEventTimeout(&e, t.controller.computer_thinking() || sound.pending()
                                                    ? 30
                                                : drew_moving ? 20
                                                              : 500) != 0;
            bool had_event = false;
            while (have || SDL_PollEvent(&e)) {
                have = false;
                had_event = true;
                ImGui_ImplSDL2_ProcessEvent(&e);
                const bool ui = ImGui::GetIO().WantCaptureMouse;
                switch (e.type) {
                    case SDL_QUIT:
                        t.exit_requested = true;
                        break;
                    case SDL_MOUSEMOTION:
                        mouse_x = e.motion.x;
                        mouse_y = e.motion.y;
                        input.motion(mouse_x, mouse_y, key_shift());
                        break;
                    case SDL_MOUSEBUTTONDOWN:
                    case SDL_MOUSEBUTTONUP: {
                        mouse_x = e.button.x;
                        mouse_y = e.button.y;
                        const bool down = e.type == SDL_MOUSEBUTTONDOWN;
                        const int slot = e.button.button == SDL_BUTTON_LEFT    ? 0
                                         : e.button.button == SDL_BUTTON_RIGHT ? 1
                                                                               : 2;
                        mouse_down[slot] = down;
                        if (down) mouse_pressed[slot] = true;
                        const MouseButton b = slot == 0   ? MouseButton::left
                                              : slot == 1 ? MouseButton::right
                                                          : MouseButton::middle;
                        if (down && !ui && !over_panel(mouse_x)) input.press(b, mouse_x, mouse_y);
                        if (!down) input.release(b, mouse_x, mouse_y);
                        break;
                    }
                    case SDL_MOUSEWHEEL:
                        if (!over_panel(mouse_x)) input.wheel(static_cast<float>(e.wheel.y));
                        break;
                    case SDL_KEYDOWN:
                        // Not while a dialog is open: its buttons answer it, the table waits.
                        if (!ImGui::GetIO().WantTextInput &&
                            !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId))
                            on_key(t, window, e.key.keysym.sym, e.key.keysym.mod);
                        break;
                    case SDL_WINDOWEVENT:
                        if (e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED &&
                            !(SDL_GetWindowFlags(window) & SDL_WINDOW_FULLSCREEN_DESKTOP)) {
                            t.setup.settings.window_width = e.window.data1;
                            t.setup.settings.window_height = e.window.data2;
                        }
                        break;
                    default:
                        break;
                }
            }
            warm_frames = had_event ? 3 : std::max(0, warm_frames - 1);

            // ---- Update
            const auto now = std::chrono::steady_clock::now();
            const double dt = std::min(0.1, std::chrono::duration<double>(now - last).count());
            last = now;
            auto signature = [&] {
                return std::tuple(t.controller.shot_serial(), t.controller.busy(),
                                  t.controller.computer_thinking(), t.controller.session().phase(),
                                  t.controller.session().game_number());
            };
            const auto before = signature();
            t.controller.update(dt);
            t.rig.update(dt);
            t.follow_cue_ball();
            if (t.controller.shot_serial() != sound_serial) {
                sound_serial = t.controller.shot_serial();
                if (t.controller.moving()) sound.start(t.controller.playback().shot());
            }
            sound.set_muted(!t.setup.settings.sound);
            if (t.controller.moving() && t.controller.playback().time() >= 0.0)
                sound.update(t.controller.playback().time());
            else if (!t.controller.moving())
                sound.advance(dt);  // a potted ball still runs to the return
            const bool redraw =
                had_event || animating || signature() != before || (drew_moving && settled());
            if (!redraw) continue;

            // ---- Draw
            int w = 0, h = 0;
            SDL_GL_GetDrawableSize(window, &w, &h);
            const PanelLayout layout = panel_layout(w, h, ui_scale);
            paint_the_session_table();
            painter->resize(w, h, static_cast<int>(layout.width));
            set_ui_scale(layout.scale);
            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplSDL2_NewFrame();
            // ImGui 1.86's SDL backend reads the global mouse state, stale under Xvfb/XTEST:
            // feed the position and buttons from the events instead.
            ImGuiIO& io = ImGui::GetIO();
            io.MousePos = ImVec2(static_cast<float>(mouse_x), static_cast<float>(mouse_y));
            for (int i = 0; i < 3; ++i) {
                io.MouseDown[i] = mouse_down[i] || mouse_pressed[i];
                mouse_pressed[i] = false;
            }
            ImGui::NewFrame();
            const PanelActions actions =
                draw_panel(t.controller, t.setup.settings, t.panel, static_cast<float>(w),
                           static_cast<float>(h), layout.width);
            ImGui::Render();
            t.apply(actions);
            if (!mouse_down[0] && !mouse_down[1] && !mouse_down[2])
                t.persist_settings();  // not mid-drag
            const float aspect =
                static_cast<float>(painter->view_width()) / static_cast<float>(painter->height());
            const render::Camera previous = t.last_camera;
            t.last_camera = t.camera(aspect);
            bool camera_moving = t.rig.animating() || previous.eye != t.last_camera.eye ||
                                 previous.target != t.last_camera.target;
            if (camera_moving) last_motion = std::chrono::steady_clock::now();
            camera_moving = camera_moving || (drew_moving && !settled());
            drew_moving = camera_moving;
            sound.set_listener(listener_of(t.last_camera));
            const SceneFrame scene =
                build_scene(t.controller, t.setup.settings.aim_guide, input.dragged_to());
            painter->draw_table(scene, t.last_camera, camera_moving);
            painter->show(ImGui::GetDrawData());
            SDL_GL_SwapWindow(window);
            ++frames;
            if (status)
                status->write(
                    status_json(t.controller, t.setup.settings, t.rig.mode(),
                                {t.panel.widgets,
                                 frames,
                                 scene.cue.has_value(),
                                 scene.show_aim,
                                 scene.ball_in_hand.has_value(),
                                 static_cast<int>(scene.aim.marks.size()),
                                 scene.show_aim && scene.aim.illegal,
                                 {w, h},
                                 static_cast<int>(layout.width),
                                 t.link_note_shown(),
                                 ball_pixels(t, painter->view_width(), painter->height())}));
        }
        t.save_and_close();
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplSDL2_Shutdown();
        destroy_imgui();
    }
    SDL_GL_DeleteContext(gl);
    SDL_DestroyWindow(window);
    SDL_Quit();
    return 0;
}

int run_screenshot(const AppOptions& options) {
    std::optional<GameSetup> setup = set_up_or_report(options);
    if (!setup) return 2;
    try {
        render::HeadlessContext context;
        const int w = setup->settings.window_width, h = setup->settings.window_height;
        Table t(std::move(*setup));
        create_imgui();
        ImGui_ImplOpenGL3_Init("#version 330 core");
        Painter painter(t.controller.session().table(),
                        t.controller.session().config().params.ball_radius);
        const PanelLayout layout =
            panel_layout(w, h, dpi_scale(std::getenv("COOLAABER_UI_SCALE"), 0.0f));
        painter.resize(w, h, static_cast<int>(layout.width));
        set_ui_scale(layout.scale);
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(static_cast<float>(w), static_cast<float>(h));
        io.DeltaTime = 1.0f / 60.0f;
        t.follow_cue_ball();
        for (int frame = 0; frame < 2; ++frame) {  // ImGui lays its windows out on the first frame
            ImGui_ImplOpenGL3_NewFrame();
            ImGui::NewFrame();
            (void)draw_panel(t.controller, t.setup.settings, t.panel, static_cast<float>(w),
                             static_cast<float>(h), layout.width);
            ImGui::Render();
        }
        const float aspect =
            static_cast<float>(painter.view_width()) / static_cast<float>(painter.height());
        t.rig.update(10.0);
        t.last_camera = t.camera(aspect);
        painter.draw_table(build_scene(t.controller, t.setup.settings.aim_guide), t.last_camera);
        if (!render::write_png(options.screenshot->string(), painter.capture(ImGui::GetDrawData())))
            throw std::runtime_error("cannot write " + options.screenshot->string());
        ImGui_ImplOpenGL3_Shutdown();
        destroy_imgui();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "coolaaber: --screenshot: %s\n", e.what());
        return 1;
    }
    return 0;
}

}  // namespace app
