#include "app/table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <numbers>
#include <system_error>

#include "app/match_setup.hpp"
#include "app/picking.hpp"
#include "app/seats.hpp"
#include "app/shot_sharing.hpp"
#include "game/atomic_file.hpp"
#include "game/state_json.hpp"
#include "game/text_file.hpp"

namespace app {

namespace {

CameraMode camera_mode(ViewMode v) {
    return v == ViewMode::overhead ? CameraMode::overhead : CameraMode::cue_ball;
}

glm::vec2 cue_ball_at(const Controller& c) {
    for (const physics::BallState& b : c.balls_now())
        if (b.id == c.cue_ball_id())
            return {static_cast<float>(b.pos.x), static_cast<float>(b.pos.y)};
    const physics::Vec2 h = c.session().table().head_spot();
    return {static_cast<float>(h.x), static_cast<float>(h.y)};
}

}  // namespace

Table::Table(GameSetup s)
    : setup(std::move(s)),
      controller(std::move(*setup.session), setup.controller),
      rig(camera_mode(setup.settings.view)) {
    panel.notice = setup.notice;
    panel.notice_is_error = setup.notice_is_error;
    saved = setup.settings;
    controller.set_power(setup.settings.power);
    if (setup.snooker) controller.start_snooker(std::move(*setup.snooker), setup.controller);
    if (setup.carom) controller.start_carom(std::move(*setup.carom), setup.controller);
    // Practice after a resumed match: that match stays saved as it was.
    if (setup.practice) start_practice(*setup.practice);
    setup.snooker.reset();
    setup.carom.reset();
    if (setup.shared_shot) {
        open_shot(controller, std::move(*setup.shared_shot),
                  seat_names(setup.settings.names, setup.controller.players), setup.controller);
        setup.shared_shot.reset();
        note_link(
            "Opened a shot link: the shot plays as it was shared; Replay (P) shows it "
            "again, or play on from where it leaves the balls.",
            false);
    }
}

std::string Table::link_note_shown() const {
    return panel.link_note_serial == controller.shot_serial() ? panel.link_note : "";
}

void Table::note_link(std::string text, bool is_error) {
    panel.link_note = std::move(text);
    panel.link_note_is_error = is_error;
    panel.link_note_serial = controller.shot_serial();
}

void Table::copy_link(platform::Window& window) {
    const ShotToShare s = shot_to_share(controller);
    if (!s.shot) return note_link(s.why_not, true);
    if (const std::optional<std::string> why = window.copy_link(game::shot_link(*s.shot)))
        return note_link("The clipboard could not be written: " + *why, true);
    note_link(copied_notice(s), false);
}

void Table::open_link(const std::string& text, LinkFrom from) {
    const bool pasted = from == LinkFrom::paste;
    std::optional<game::AnyShot> shot;
    try {
        shot = game::read_any_shot_link(text);
    } catch (const game::LoadError& e) {
        return note_link(
            std::string(pasted ? "The pasted text is not" : "The page's address does not hold") +
                " a shot link this game can open: " + e.what(),
            true);
    }
    ControllerOptions opts = setup.controller;
    opts.players = setup.settings.players;
    opts.seed = fresh_seed();
    open_shot(controller, std::move(*shot), seat_names(setup.settings.names, opts.players), opts);
    note_link(std::string(pasted ? "Opened the pasted shot link"
                                 : "Opened the shot link in the page's address") +
                  ": Replay (P) shows it again, or play on.",
              false);
}

void Table::paste_link(const platform::Window& window) {
    const std::string pasted = window.clipboard();
    if (pasted.empty()) return note_link("The clipboard is empty: copy a shot link first.", true);
    open_link(pasted, LinkFrom::paste);
}

void Table::start_practice(physics::RackType game) {
    ControllerOptions opts = setup.controller;
    opts.seed = fresh_seed();
    controller.start_practice(game::Practice::on_own_table(game, opts.seed), opts);
}

void Table::save_position() {
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

void Table::load_position() {
    try {
        game::Practice p = game::Practice::from_json(game::read_regular_file(setup.position_path));
        ControllerOptions opts = setup.controller;
        opts.seed = fresh_seed();
        controller.start_practice(std::move(p), opts);
        note_link("Loaded the position from " + setup.position_path.string() + ".", false);
    } catch (const game::LoadError& e) {
        note_link(std::string("The position could not be loaded: ") + e.what(), true);
    }
}

render::Camera Table::camera(float aspect) const {
    return rig.camera(controller.session().table(), aspect);
}

void Table::follow_cue_ball() {
    if (controller.moving()) return;
    const float heading =
        static_cast<float>(controller.aim().heading_deg * std::numbers::pi / 180.0);
    const float elevation =
        static_cast<float>(controller.aim().elevation_deg * std::numbers::pi / 180.0);
    rig.set_anchor(cue_ball_at(controller), heading, true, last_camera, elevation);
}

void Table::set_power(double power) {
    controller.set_power(power);
    setup.settings.power = std::clamp(power, 0.0, 1.0);
}

void Table::change_view() {
    rig.next_view(last_camera);
    setup.settings.view =
        rig.mode() == CameraMode::cue_ball ? ViewMode::cue_ball : ViewMode::overhead;
}

void Table::apply(const PanelActions& a, platform::Window* window) {
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
    if (a.copy_link && window) copy_link(*window);
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
    if (a.new_game) start_new_game(*a.new_game);
}

void Table::start_new_game(const NewGame& choice) {
    Settings& s = setup.settings;
    s.game = choice.game;
    s.names = choice.names;
    s.players = choice.players;
    s.house_rules = choice.house_rules;
    s.aim_guide = choice.aim_guide;
    ControllerOptions opts = setup.controller;
    opts.players = s.players;
    opts.seed = fresh_seed();
    panel.link_note.clear();  // a saved or loaded position's note belongs to the last game
    try {
        if (choice.practice) return start_practice(practice_game(choice));
        if (choice.table != TableGame::pool) return start_match(controller, choice, opts);
        controller.replace(game::Session(new_game_config(s, opts.seed)), opts);
    } catch (const std::exception& e) {
        panel.notice = e.what();
        panel.notice_is_error = true;
    }
}

void Table::persist_settings() {
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

std::string Table::save_game() const {
    // Practice is not a game: the game saved before it stays as it was.
    if (controller.practicing()) return {};
    if (const game::SnookerSession* m = controller.snooker())
        return save_on_exit(*m, setup.autosave_path);
    if (const game::CaromSession* m = controller.carom())
        return save_on_exit(*m, setup.autosave_path);
    return save_on_exit(controller.session(), setup.autosave_path);
}

void Table::save_and_close() {
    const std::string err = save_game();
    if (!err.empty()) std::fprintf(stderr, "coolaaber: the game was not saved: %s\n", err.c_str());
    if (setup.settings_path.empty()) return;
    try {
        save_settings(setup.settings_path, setup.settings);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "coolaaber: the settings were not saved: %s\n", e.what());
    }
}

std::string table_key(const Controller& c) {
    const game::Session& s = c.session();
    return game::to_json(s.config().table).dump() +
           fmt::format("{} {}", s.config().params.ball_radius, static_cast<int>(c.look()));
}

std::map<int, std::array<double, 2>> ball_pixels(const Table& t, int width, int height) {
    std::map<int, std::array<double, 2>> out;
    const double R = t.controller.session().config().params.ball_radius;
    for (const physics::BallState& b : t.controller.balls_now())
        if (auto px = screen_point(t.last_camera, width, height, b.pos, R)) out[b.id] = *px;
    return out;
}

void on_key(Table& t, platform::Window& window, const platform::Event& e) {
    using platform::Key;
    switch (e.key) {
        case Key::left:
            return t.controller.turn_aim(e.shift ? 0.05 : 0.5);
        case Key::right:
            return t.controller.turn_aim(e.shift ? -0.05 : -0.5);
        case Key::up:
            return t.set_power(t.controller.aim().power + 0.05);
        case Key::down:
            return t.set_power(t.controller.aim().power - 0.05);
        case Key::space:
            return t.controller.strike();
        case Key::v:
            return e.ctrl ? t.paste_link(window) : t.change_view();
        case Key::s:
        case Key::enter:
            return t.controller.skip();
        case Key::p:
            return t.controller.replay();
        case Key::h:
            return t.controller.hint();
        case Key::g:
            t.setup.settings.aim_guide = next_aim_guide(t.setup.settings.aim_guide);
            return;
        case Key::o:
            return t.rig.set_mode(
                t.rig.mode() == CameraMode::free ? CameraMode::overhead : CameraMode::free,
                t.last_camera);
        case Key::r:
            t.panel.confirm_restart = true;
            return;
        case Key::escape:
            t.panel.menu = true;
            return;
        case Key::f11:
            t.setup.settings.fullscreen = !window.fullscreen();
            window.set_fullscreen(t.setup.settings.fullscreen);
            return;
        case Key::other:
            return;
    }
}

}  // namespace app
