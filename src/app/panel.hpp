// The side panel (Dear ImGui): the original game's controls — Power, Sound, Change View,
// Restart, Exit — the information bar under them, and the additions: spin, elevation, calls,
// push-out, the rules' choices, aim guide, skip/replay, New Game. Drawing the panel only
// reports what the player asked for (PanelActions); the app applies it after the frame.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "app/controller.hpp"
#include "app/panel_layout.hpp"
#include "app/settings.hpp"
#include "rules/snooker.hpp"
#include "rules/three_cushion.hpp"

namespace app {

/// Which table a New Game is played on: pool (`NewGame::game` says 8-ball or 9-ball), snooker
/// or three-cushion.
enum class TableGame { pool, snooker, three_cushion };

/// A New Game as the dialog sets it up.
struct NewGame {
    TableGame table = TableGame::pool;
    rules::Game game = rules::Game::eight_ball;
    std::array<std::string, 2> names{"Player 1", "Player 2"};
    std::array<std::string, 2> players{"human", "human"};
    rules::Options house_rules;
    AimGuide aim_guide = AimGuide::lines;
    bool practice = false;          ///< one player at this game's table and balls, no rules
    rules::SnookerOptions snooker;  ///< the miss rule
    int best_of = 1;                ///< snooker: frames in the match
    rules::CaromOptions carom;      ///< points to win, equal innings
};

struct PanelActions {
    std::optional<double> power;
    std::optional<bool> sound;
    std::optional<AimGuide> aim_guide;
    bool change_view = false;
    bool restart = false;  ///< confirmed
    bool exit = false;
    bool skip = false;
    bool replay = false;
    bool strike = false;
    bool hint = false;
    bool copy_link = false;  ///< Copy shot link
    bool try_again = false;  ///< practice: the position before the last shot
    bool save_position = false;
    bool load_position = false;
    std::optional<std::pair<double, double>> spin;  ///< side, top (unit: R)
    std::optional<double> elevation_deg;
    std::optional<rules::ChoiceOption> choice;
    std::optional<bool> push_out;
    bool call_safety = false;
    bool clear_call = false;
    std::optional<NewGame> new_game;
    std::optional<rules::AfterFoul> after_foul;  ///< snooker: the choice after a foul
    std::optional<std::optional<int>> nominate;  ///< snooker: a ball, or back to the aim's
    bool next_frame = false;                     ///< snooker: next frame; carom: next game
};

/// What the panel keeps between frames (which dialog is open, the New Game draft).
struct PanelState {
    bool confirm_restart = false;  ///< ask "Restart this game?"
    bool menu = false;             ///< the Esc menu
    bool new_game_open = false;
    bool controls_open = false;  ///< the Controls help
    NewGame draft;
    std::string notice;            ///< a message shown once at the top (e.g. a bad settings file)
    bool notice_is_error = false;  ///< drawn as a warning (else as news)
    /// What a shot link copied or pasted did, in the information bar until the next shot
    /// (the controller's shot_serial() other than `link_note_serial`).
    std::string link_note;
    bool link_note_is_error = false;
    int link_note_serial = 0;
    /// Where each labelled widget was drawn last frame (unit: px, window frame: x0, y0, x1, y1),
    /// for the status file that end-to-end tests click by.
    std::map<std::string, std::array<float, 4>> widgets;
};

/// Draws the panel where `layout` puts it in a `width` × `height` window: at the right, the
/// original controls at the top and the play buttons at the bottom always show, the information
/// bar and the stroke's controls between them scroll when the window is too low; below the
/// table, the information bar heads the scrolling part and Power, Strike, Hint, Change View
/// and Skip or Replay stay at the foot. Call between ImGui::NewFrame() and ImGui::Render().
PanelActions draw_panel(const Controller& controller, const Settings& settings, PanelState& state,
                        float width, float height, const PanelLayout& layout);

}  // namespace app
