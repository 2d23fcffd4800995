// coolaaber: the game. Options (docs/app.md):
//   --size WxH  --fullscreen  --game 8ball|9ball|snooker|three_cushion  --load FILE  --shot LINK
//   --practice
//   --view overhead|cueball
//   --screenshot FILE (render the first frame offscreen, write a PNG, exit)
//   --players human,ai:3  --seed N  --noise X  --playback-speed X  --status-file FILE (tests)
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>

#include "app/app.hpp"
#include "app/settings.hpp"

namespace {

// The options as given on the command line, before they are read into app::AppOptions.
struct CommandLine {
    app::AppOptions options;
    std::string size, game, view, players;
    std::string load, shot, screenshot, status;
    std::uint64_t seed = 0;
    CLI::Option* seed_given = nullptr;
    double noise = -1.0;
};

// A bad option value: "error: <option>: <message>", exit status 2.
struct BadOption : std::runtime_error {
    using std::runtime_error::runtime_error;
};

void add_options(CLI::App& cli, CommandLine& line) {
    app::AppOptions& o = line.options;
    cli.add_option("--size", line.size, "window size WIDTHxHEIGHT, e.g. 1280x720");
    cli.add_flag("--fullscreen", o.fullscreen, "start in fullscreen (F11 toggles)");
    cli.add_option("--game", line.game, "start a new game: 8ball, 9ball, snooker or three_cushion")
        ->check(CLI::IsMember({"8ball", "9ball", "snooker", "three_cushion"}));
    CLI::Option* load = cli.add_option("--load", line.load, "resume a saved game from FILE");
    cli.add_option("--shot", line.shot,
                   "open a shot link (shot=1.… or an address ending in #shot=1.…) and play it")
        ->excludes(load);
    cli.add_flag("--practice", o.practice,
                 "practise alone at the game's table and balls (see --game), no rules");
    cli.add_option("--view", line.view, "overhead or cueball")
        ->check(CLI::IsMember({"overhead", "cueball"}));
    cli.add_option("--screenshot", line.screenshot,
                   "render the first frame offscreen into a PNG and exit");
    cli.add_option("--players", line.players,
                   "who plays: two of human, random, ai:1 ... ai:5 (e.g. human,ai:3)");
    line.seed_given =
        cli.add_option("--seed", line.seed, "seed of the racks and the computer players");
    cli.add_option("--noise", line.noise,
                   "execution noise of computer players (0 none, 1 standard)")
        ->check(CLI::Range(0.0, 10.0));
    cli.add_option("--playback-speed", o.playback_speed, "shot playback speed; 0 jumps to the end")
        ->check(CLI::Range(0.0, 100.0));
    cli.add_option("--status-file", line.status,
                   "test hook: write what the player sees as JSON to FILE");
}

void read_size(const std::string& size, app::AppOptions& o) {
    int w = 0, h = 0;
    char tail = 0;
    if (std::sscanf(size.c_str(), "%dx%d%c", &w, &h, &tail) != 2 || w < 320 || h < 240 ||
        w > 16384 || h > 16384)
        throw BadOption("--size: expected WIDTHxHEIGHT of at least 320x240, e.g. 1280x720");
    o.width = w;
    o.height = h;
}

std::array<std::string, 2> read_players(const std::string& players) {
    const auto comma = players.find(',');
    std::array<std::string, 2> p{players.substr(0, comma),
                                 comma == std::string::npos ? "" : players.substr(comma + 1)};
    for (const std::string& k : p)
        if (!app::valid_player_kind(k))
            throw BadOption("--players: \"" + k +
                            "\" is not a player (expected two of human, random, ai:1 ... ai:5, "
                            "e.g. human,ai:3)");
    return p;
}

// The options given, read into the game's options; a bad value throws BadOption.
app::AppOptions read_options(const CommandLine& line) {
    app::AppOptions o = line.options;
    if (!line.size.empty()) read_size(line.size, o);
    if (!line.game.empty())
        o.game = line.game == "8ball"     ? physics::RackType::eight_ball
                 : line.game == "9ball"   ? physics::RackType::nine_ball
                 : line.game == "snooker" ? physics::RackType::snooker
                                          : physics::RackType::three_cushion;
    if (!line.view.empty())
        o.view = line.view == "overhead" ? app::ViewMode::overhead : app::ViewMode::cue_ball;
    if (!line.load.empty()) o.load = line.load;
    if (!line.shot.empty()) o.shot = line.shot;
    if (!line.screenshot.empty()) o.screenshot = line.screenshot;
    if (!line.status.empty()) o.status_file = line.status;
    if (*line.seed_given) o.seed = line.seed;
    if (line.noise >= 0.0) o.noise = line.noise;
    if (!line.players.empty()) o.players = read_players(line.players);
    return o;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App cli{"Coolaaber: a game of pool (8-ball and 9-ball)", "coolaaber"};
    CommandLine line;
    add_options(cli, line);
    app::AppOptions o;
    try {
        cli.parse(argc, argv);
        o = read_options(line);
    } catch (const CLI::ParseError& e) {
        return cli.exit(e) == 0 ? 0 : 2;
    } catch (const BadOption& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
    }
    try {
        return o.screenshot ? app::run_screenshot(o) : app::run_window(o);
    } catch (const std::exception& e) {  // e.g. a missing font package, a GL resource failure
        std::fprintf(stderr, "coolaaber: %s\n", e.what());
        return 1;
    }
}
