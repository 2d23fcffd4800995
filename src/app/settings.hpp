// What the game remembers between runs: view, sound, power, names, players, house rules and the
// window. Stored as JSON in the XDG config folder ($XDG_CONFIG_HOME/coolaaber/settings.json,
// default ~/.config/coolaaber/settings.json). A file that does not read is kept aside (renamed)
// and the defaults are used, with a message that says so.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "rules/game_state.hpp"
#include "rules/options.hpp"

namespace app {

enum class ViewMode { overhead, cue_ball };

/// How much the aim guide shows (docs/app.md, "Aim guide").
enum class AimGuide {
    off,       ///< nothing
    ghost,     ///< the line to the ghost ball, and the ghost ball
    lines,     ///< and short lines: the object ball's direction, the cue ball's tangent line
    practice,  ///< the simulated paths of both balls, and where the object ball's path ends
};

/// "off", "ghost", "lines", "practice" (the settings file's names).
std::string_view aim_guide_name(AimGuide g);
/// The next level (the G key): off, ghost, lines, practice, off...
AimGuide next_aim_guide(AimGuide g);
/// "Off", "Ghost ball", ... (the panel's names).
const char* aim_guide_words(AimGuide g);

struct Settings {
    rules::Game game = rules::Game::eight_ball;
    ViewMode view = ViewMode::overhead;
    bool sound = true;
    double power = 0.45;  ///< the Power slider (unit: 0–1 of the strongest stroke)
    AimGuide aim_guide = AimGuide::lines;
    std::array<std::string, 2> names{"Player 1", "Player 2"};
    /// Who plays each seat: "human", "random", or "ai:1" … "ai:5".
    std::array<std::string, 2> players{"human", "human"};
    double noise = 1.0;  ///< execution-noise scale for computer players (unit: 1)
    rules::Options house_rules;
    int window_width = 1280;  ///< (unit: px)
    int window_height = 720;  ///< (unit: px)
    bool fullscreen = false;

    friend bool operator==(const Settings&, const Settings&) = default;
};

/// The settings folder: $XDG_CONFIG_HOME/coolaaber, else $HOME/.config/coolaaber.
std::filesystem::path config_folder();
/// The folder of the game saved on exit: $XDG_DATA_HOME/coolaaber, else ~/.local/share/coolaaber.
std::filesystem::path data_folder();

/// Whether `kind` names a seat's player ("human", "random", "ai:1" … "ai:5").
bool valid_player_kind(const std::string& kind);

std::string settings_to_json(const Settings& s);
/// Throws game::LoadError naming the field ("settings.power: ...") for a document that is not
/// valid settings. Fields left out keep their defaults; unknown fields are errors.
Settings settings_from_json(const std::string& text);

struct LoadedSettings {
    Settings settings;
    std::optional<std::string> message;  ///< set when the file was bad and was kept aside
    /// A bad file that could not be renamed: it stays where it was and must not be written over.
    bool left_in_place = false;
};

/// Reads `path`; a missing file gives the defaults silently; a bad one is renamed to
/// `<path>.bad` (or `.bad-2` …) and gives the defaults with a message naming the error.
LoadedSettings load_settings(const std::filesystem::path& path);
/// Writes atomically, creating the folder. Throws std::runtime_error when it cannot.
void save_settings(const std::filesystem::path& path, const Settings& s);

/// `path` renamed aside to the first free `<path>.bad`, `<path>.bad-2`, …; returns the new name
/// (empty if the rename failed).
std::filesystem::path keep_aside(const std::filesystem::path& path);

}  // namespace app
