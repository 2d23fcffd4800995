#include "app/game_setup.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>

#include "app/seats.hpp"
#include "app/shot_sharing.hpp"
#include "game/json_field.hpp"
#include "game/text_file.hpp"

namespace app {

namespace {

// The saved game at `path`, of whichever game its "format" names (a pool session when it
// names none it knows: that reader says what is wrong). Throws game::LoadError.
void load_saved_game(GameSetup& g, const std::filesystem::path& path) {
    const std::string text = game::read_regular_file(path);
    const nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
    const std::string format =
        doc.is_object() && doc.contains("format") && doc["format"].is_string()
            ? doc["format"].get<std::string>()
            : std::string();
    if (format == "coolaaber-snooker")
        g.snooker = game::SnookerSession::from_json(text);
    else if (format == "coolaaber-three-cushion")
        g.carom = game::CaromSession::from_json(text);
    else
        g.session = game::Session::from_json(text);
}

// Writes `match` over `path` unless it is `finished` (then the old save goes).
template <class Match>
std::string save_match(const Match& match, bool finished, const std::filesystem::path& path) {
    if (path.empty()) return {};
    std::error_code ec;
    try {
        if (finished) {
            std::filesystem::remove(path, ec);
            return {};
        }
        std::filesystem::create_directories(path.parent_path(), ec);
        match.save_file(path);
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

// --game snooker or three_cushion (not practice): a new match on its own table, the seats as
// the settings say, in front of the pool session.
void new_match(GameSetup& g, std::optional<physics::RackType> game) {
    const Settings& s = g.settings;
    if (game == physics::RackType::snooker) {
        game::SnookerConfig c;
        c.names = seat_names(s.names, s.players);
        g.snooker.emplace(std::move(c));
    } else if (game == physics::RackType::three_cushion) {
        game::CaromConfig c;
        c.names = seat_names(s.names, s.players);
        g.carom.emplace(std::move(c));
    }
}

}  // namespace

std::uint64_t fresh_seed() {
    return static_cast<std::uint64_t>(std::chrono::system_clock::now().time_since_epoch().count());
}

game::Config new_game_config(const Settings& s, std::uint64_t seed) {
    game::Config c;
    c.game = s.game;
    c.options = s.house_rules;
    c.names = seat_names(s.names, s.players);
    c.seed = seed;
    return c;
}

GameSetup set_up_game(const AppOptions& o) {
    GameSetup g;
    g.settings_path = config_folder() / "settings.json";
    g.autosave_path = data_folder() / "saved-game.json";
    g.position_path = data_folder() / "practice-position.json";
    LoadedSettings loaded = load_settings(g.settings_path);
    g.settings = loaded.settings;
    if (loaded.message) {
        g.notice = *loaded.message;
        g.notice_is_error = true;
    }
    if (loaded.left_in_place) g.settings_path.clear();
    Settings& s = g.settings;
    if (o.width) s.window_width = *o.width;
    if (o.height) s.window_height = *o.height;
    if (o.fullscreen) s.fullscreen = true;
    if (o.view) s.view = *o.view;
    if (o.players) s.players = *o.players;
    if (o.noise) s.noise = *o.noise;
    if (o.game == physics::RackType::eight_ball) s.game = rules::Game::eight_ball;
    if (o.game == physics::RackType::nine_ball) s.game = rules::Game::nine_ball;
    if (o.practice)
        g.practice =
            o.game.value_or(s.game == rules::Game::eight_ball ? physics::RackType::eight_ball
                                                              : physics::RackType::nine_ball);

    const std::uint64_t seed = o.seed.value_or(fresh_seed());
    g.controller.players = s.players;
    g.controller.noise = s.noise;
    g.controller.seed = seed;
    g.controller.playback_speed = o.playback_speed;

    if (o.shot) {
        g.shared_shot = game::read_any_shot_link(*o.shot);  // LoadError to the caller
        g.session.emplace(new_game_config(s, seed));        // replaced by the shot's
        return g;
    }
    if (o.load) {
        load_saved_game(g, *o.load);  // a bad file: LoadError to the caller
        if (!g.session) g.session.emplace(new_game_config(s, seed));
        return g;
    }
    std::error_code ec;
    if (!o.game && std::filesystem::exists(g.autosave_path, ec)) {
        try {
            load_saved_game(g, g.autosave_path);
            if (g.notice.empty()) g.notice = "Resumed the game saved when you last exited.";
            if (!g.session) g.session.emplace(new_game_config(s, seed));  // behind the match
            return g;
        } catch (const game::LoadError& e) {
            const std::filesystem::path aside = keep_aside(g.autosave_path);
            const std::string kept =
                aside.empty() ? "it could not be renamed, so it is left as it is and this game "
                                "will not be saved over it"
                              : "it was kept as " + aside.string();
            g.notice_is_error = true;
            g.notice += fmt::format("{}The saved game could not be resumed ({}); {}.",
                                    g.notice.empty() ? "" : "\n", e.what(), kept);
            if (aside.empty()) g.autosave_path.clear();
        }
    }
    g.session.emplace(new_game_config(s, seed));
    if (!o.practice) new_match(g, o.game);
    return g;
}

std::string save_on_exit(const game::Session& session, const std::filesystem::path& path) {
    if (path.empty()) return {};
    std::error_code ec;
    try {
        if (session.phase() == game::Phase::game_over) {
            std::filesystem::remove(path, ec);
            return {};
        }
        std::filesystem::create_directories(path.parent_path(), ec);
        session.save_file(path);
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

std::string save_on_exit(const game::SnookerSession& match, const std::filesystem::path& path) {
    return save_match(match, match.phase() == game::MatchPhase::match_over, path);
}

std::string save_on_exit(const game::CaromSession& match, const std::filesystem::path& path) {
    return save_match(match, match.game_over(), path);
}

std::optional<GameSetup> set_up_or_report(const AppOptions& options) {
    try {
        return set_up_game(options);
    } catch (const game::LoadError& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return std::nullopt;
    }
}

}  // namespace app
