// coolaaber: the game. Options (docs/app.md):
//   --size WxH  --fullscreen  --game 8ball|9ball  --load FILE  --view overhead|cueball
//   --screenshot FILE (render the first frame offscreen, write a PNG, exit)
//   --players human,ai:3  --seed N  --noise X  --playback-speed X  --status-file FILE (tests)
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "app/app.hpp"
#include "app/settings.hpp"

int main(int argc, char** argv) {
    CLI::App cli{"Coolaaber: a game of pool (8-ball and 9-ball)", "coolaaber"};
    app::AppOptions o;
    std::string size, game, view, players;
    std::string load, screenshot, status;
    std::uint64_t seed = 0;
    double noise = -1.0;
    cli.add_option("--size", size, "window size WIDTHxHEIGHT, e.g. 1280x720");
    cli.add_flag("--fullscreen", o.fullscreen, "start in fullscreen (F11 toggles)");
    cli.add_option("--game", game, "start a new game: 8ball or 9ball")
        ->check(CLI::IsMember({"8ball", "9ball"}));
    cli.add_option("--load", load, "resume a saved game from FILE");
    cli.add_option("--view", view, "overhead or cueball")
        ->check(CLI::IsMember({"overhead", "cueball"}));
    cli.add_option("--screenshot", screenshot,
                   "render the first frame offscreen into a PNG and exit");
    cli.add_option("--players", players,
                   "who plays: two of human, random, ai:1 ... ai:5 (e.g. human,ai:3)");
    auto* seed_opt = cli.add_option("--seed", seed, "seed of the racks and the computer players");
    cli.add_option("--noise", noise, "execution noise of computer players (0 none, 1 standard)")
        ->check(CLI::Range(0.0, 10.0));
    cli.add_option("--playback-speed", o.playback_speed, "shot playback speed; 0 jumps to the end")
        ->check(CLI::Range(0.0, 100.0));
    cli.add_option("--status-file", status,
                   "test hook: write what the player sees as JSON to FILE");
    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return cli.exit(e) == 0 ? 0 : 2;
    }
    if (!size.empty()) {
        int w = 0, h = 0;
        char tail = 0;
        if (std::sscanf(size.c_str(), "%dx%d%c", &w, &h, &tail) != 2 || w < 320 || h < 240 ||
            w > 16384 || h > 16384) {
            std::fprintf(
                stderr,
                "error: --size: expected WIDTHxHEIGHT of at least 320x240, e.g. 1280x720\n");
            return 2;
        }
        o.width = w;
        o.height = h;
    }
    if (!game.empty()) o.game = game == "8ball" ? rules::Game::eight_ball : rules::Game::nine_ball;
    if (!view.empty())
        o.view = view == "overhead" ? app::ViewMode::overhead : app::ViewMode::cue_ball;
    if (!load.empty()) o.load = load;
    if (!screenshot.empty()) o.screenshot = screenshot;
    if (!status.empty()) o.status_file = status;
    if (*seed_opt) o.seed = seed;
    if (noise >= 0.0) o.noise = noise;
    if (!players.empty()) {
        const auto comma = players.find(',');
        std::array<std::string, 2> p{players.substr(0, comma),
                                     comma == std::string::npos ? "" : players.substr(comma + 1)};
        for (const std::string& k : p)
            if (!app::valid_player_kind(k)) {
                std::fprintf(stderr,
                             "error: --players: \"%s\" is not a player (expected two of human, "
                             "random, ai:1 ... ai:5, e.g. human,ai:3)\n",
                             k.c_str());
                return 2;
            }
        o.players = p;
    }
    try {
        return o.screenshot ? app::run_screenshot(o) : app::run_window(o);
    } catch (const std::exception& e) {  // e.g. a missing font package, a GL resource failure
        std::fprintf(stderr, "coolaaber: %s\n", e.what());
        return 1;
    }
}
