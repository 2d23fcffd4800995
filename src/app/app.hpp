// The game program: command-line options, setting up the game (new, resumed or loaded), the
// window's main loop, and the offscreen screenshot.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "app/settings.hpp"
#include "physics/rack.hpp"
#include "rules/game_state.hpp"

namespace app {

struct AppOptions {
    std::optional<int> width, height;  ///< --size WxH (unit: px)
    bool fullscreen = false;
    /// --game: a new game of this kind (8-ball, 9-ball, snooker, three-cushion)
    std::optional<physics::RackType> game;
    std::optional<std::filesystem::path> load;  ///< --load FILE: a saved game
    std::optional<std::string> shot;            ///< --shot LINK: a shared shot, played at once
    bool practice = false;  ///< --practice: one player at the game's table and balls, no rules
    std::optional<ViewMode> view;
    std::optional<std::filesystem::path> screenshot;  ///< render the first frame to a PNG, exit
    // Test hooks and extras
    std::optional<std::array<std::string, 2>> players;  ///< --players human,ai:3
    std::optional<std::uint64_t> seed;                  ///< racks and computer players
    double playback_speed = 1.0;                        ///< 0: every shot jumps to its end
    std::optional<std::filesystem::path>
        status_file;              ///< JSON of what the player sees, each change
    std::optional<double> noise;  ///< computer players' execution noise scale
};

/// Runs the game in a window until Exit; returns the process's exit status.
int run_window(const AppOptions& options);
/// Renders the first frame offscreen (no window or display needed) and writes a PNG.
int run_screenshot(const AppOptions& options);

}  // namespace app
