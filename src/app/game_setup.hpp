// How a run of the game begins: the settings read (or kept aside when bad), then a session:
// loaded (--load), resumed (the game saved on exit), or new, and who plays each seat.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "app/app.hpp"
#include "app/controller.hpp"
#include "app/settings.hpp"
#include "game/carom_session.hpp"
#include "game/session.hpp"
#include "game/shot_link.hpp"
#include "game/snooker_session.hpp"

namespace app {

struct GameSetup {
    Settings settings;
    /// Where the settings and the game are saved; empty where a bad file could not be set
    /// aside (it is never written over).
    std::filesystem::path settings_path;
    std::filesystem::path autosave_path;
    std::optional<game::Session> session;
    /// A snooker match or three-cushion game resumed from the autosave (played in `session`'s
    /// place; `session` is then a new pool game behind it).
    std::optional<game::SnookerSession> snooker;
    std::optional<game::CaromSession> carom;
    ControllerOptions controller;
    /// A shared shot (--shot), opened in `session`'s place and played at once
    /// (shot_sharing.hpp, open_shot).
    std::optional<game::AnyShot> shared_shot;
    /// --practice: start practising at this game's table and balls
    std::optional<physics::RackType> practice;
    std::filesystem::path position_path;  ///< where Save position writes (practice)
    std::string notice;  ///< shown in the panel (a settings or saved game kept aside, a resume)
    bool notice_is_error = false;  ///< a file was bad (else: news, e.g. the game was resumed)
};

/// A new session's configuration from the settings (names, game, house rules) and a seed.
game::Config new_game_config(const Settings& settings, std::uint64_t seed);

/// Throws game::LoadError for a bad --load file or --shot link (the caller reports it and
/// exits 2).
GameSetup set_up_game(const AppOptions& options);
/// set_up_game, or empty with the reason on stderr when a --load file or --shot link is bad.
std::optional<GameSetup> set_up_or_report(const AppOptions& options);

/// A seed from the clock (a new rack each run), unless one was given.
std::uint64_t fresh_seed();

/// Saves the game on exit (an unfinished one) or removes the old save (a finished one);
/// returns an error message or empty. An empty `path` saves nothing.
std::string save_on_exit(const game::Session& session, const std::filesystem::path& path);
/// The same for a snooker match (finished: the match won) and a three-cushion game.
std::string save_on_exit(const game::SnookerSession& match, const std::filesystem::path& path);
std::string save_on_exit(const game::CaromSession& match, const std::filesystem::path& path);

}  // namespace app
