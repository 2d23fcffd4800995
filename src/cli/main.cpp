// coolaaber-cli: the headless interface to the engine (docs/cli.md).
//   coolaaber-cli simulate [FILE] [--pretty]
//   coolaaber-cli judge [FILE] [--pretty]
//   coolaaber-cli decide [FILE] [--pretty]
//   coolaaber-cli bench [--runs N] [--pretty]
//   coolaaber-cli match --game 8ball --players random,random [--games N] [--seed S] [--log FILE]
//                       [--noise X] [--duplicate] [--reds N] [--target N] [--pretty]
// Exit status: 0 success; 2 bad input (one line on stderr: "error: <json path>: <message>",
// nothing on stdout); 1 internal error.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <new>
#include <string>

#include "cli/commands.hpp"
#include "cli/flags.hpp"
#include "cli/json_in.hpp"
#include "cli/json_out.hpp"
#include "game/text_file.hpp"

namespace {

constexpr int exit_ok = 0;
constexpr int exit_internal = 1;
constexpr int exit_bad_input = 2;

// The command line as given: flag values are text until read strictly (cli/flags.hpp).
struct CommandLine {
    std::string file = "-";
    bool pretty = false;
    std::string runs = std::to_string(cli::default_bench_runs);
    cli::MatchOptions match;
    std::string games = std::to_string(cli::MatchOptions{}.games);
    std::string noise = fmt::format("{}", cli::MatchOptions{}.noise);
    std::string reds;    ///< snooker: empty, all 15
    std::string target;  ///< three-cushion: empty, the rules' default
};

struct Verbs {
    CLI::App* simulate;
    CLI::App* judge;
    CLI::App* decide;
    CLI::App* bench;
    CLI::App* match;
};

// One line on stderr: newlines in a message would break the one-line contract.
void print_error(const std::string& message) {
    std::string line = "error: " + message;
    for (char& c : line)
        if (c == '\n' || c == '\r') c = ' ';
    std::fputs((line + "\n").c_str(), stderr);
}

// Writes the whole document at once, so that a failure leaves nothing half-written.
int print_document(std::string_view text) {
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() ||
        std::fflush(stdout) != 0) {
        print_error("output: cannot write to standard output");
        return exit_internal;
    }
    return exit_ok;
}

void add_match_flags(CLI::App& match, CommandLine& line) {
    cli::MatchOptions& o = line.match;
    match.add_option("--game", o.game, "8ball, 9ball, snooker or three_cushion")
        ->capture_default_str();
    match.add_option("--players", o.players, "Two players: random, ai:LEVEL")
        ->capture_default_str();
    match.add_option("--games", line.games, "Games to play")->capture_default_str();
    match.add_option("--seed", o.seed, "Seed of the racks and the players")->capture_default_str();
    match.add_option("--log", o.log, "Write one JSON line per shot to FILE");
    match.add_option("--noise", line.noise, "Scale of the execution noise")->capture_default_str();
    match.add_flag("--duplicate", o.duplicate, "Play each seed twice, the sides swapped");
    match.add_option("--reds", line.reds, "Snooker: reds racked (1-15, default 15)");
    match.add_option("--target", line.target, "Three-cushion: points to win a game");
}

Verbs add_verbs(CLI::App& app, CommandLine& line) {
    Verbs v{};
    v.simulate = app.add_subcommand("simulate", "Simulate one shot: balls, a strike → events");
    v.judge = app.add_subcommand("judge", "Apply the rules of a game to one shot's events");
    v.decide = app.add_subcommand("decide", "The computer player's decision in a position");
    v.bench = app.add_subcommand("bench", "Time the standard scenes");
    v.match = app.add_subcommand("match", "Play whole games between two players");
    add_match_flags(*v.match, line);
    for (CLI::App* verb : {v.simulate, v.judge, v.decide})
        verb->add_option("FILE", line.file, "Input JSON document; - or absent: standard input");
    v.bench->add_option("--runs", line.runs, "Simulations per scene")->capture_default_str();
    for (CLI::App* a : {&app, v.simulate, v.judge, v.decide, v.bench, v.match})
        a->add_flag("--pretty", line.pretty, "Indent the output (default: one line)");
    return v;
}

// The input document from FILE, or standard input when FILE is "-", within the size limit.
std::string read_input(const std::string& file) {
    if (file == "-") return game::read_stream(std::cin, "-");
    if (file.empty())
        throw cli::BadInput("FILE",
                            "an empty file name: give a JSON file, or - for standard input");
    return game::read_regular_file(file);
}

// Runs the verb given; bad input throws cli::BadInput.
std::string run_verb(const Verbs& v, CommandLine& line) {
    if (v.simulate->parsed())
        return cli::run_document(cli::DocumentVerb::simulate, read_input(line.file), line.pretty);
    if (v.judge->parsed())
        return cli::run_document(cli::DocumentVerb::judge, read_input(line.file), line.pretty);
    if (v.decide->parsed())
        return cli::run_document(cli::DocumentVerb::decide, read_input(line.file), line.pretty);
    nlohmann::ordered_json out;
    if (v.bench->parsed()) {
        out = cli::bench_command(cli::read_integer_flag("--runs", line.runs));
    } else {
        cli::MatchOptions& o = line.match;
        o.games = cli::read_integer_flag("--games", line.games);
        o.noise = cli::read_number_flag("--noise", line.noise);
        if (v.match->count("--log") > 0) o.log = cli::read_file_flag("--log", o.log);
        if (v.match->count("--reds") > 0) o.reds = cli::read_integer_flag("--reds", line.reds);
        if (v.match->count("--target") > 0)
            o.target = cli::read_integer_flag("--target", line.target);
        out = cli::match_command(o);
    }
    return cli::write_document(out, line.pretty);
}

// Runs the verb and prints its document, or the error: the exit status.
int run_and_print(const Verbs& v, CommandLine& line) {
    try {
        return print_document(run_verb(v, line));
    } catch (const cli::BadInput& e) {
        print_error(e.what());
        return exit_bad_input;
    } catch (const std::bad_alloc&) {
        print_error("internal: out of memory");
        return exit_internal;
    } catch (const std::exception& e) {
        print_error(fmt::format("internal: {}", e.what()));
        return exit_internal;
    } catch (...) {
        print_error("internal: unknown error");
        return exit_internal;
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "coolaaber-cli: the Coolaaber pool engine without a window. Reads one JSON "
        "document, writes one JSON document (docs/cli.md).",
        "coolaaber-cli"};
    app.require_subcommand(1);
    app.fallthrough();
    CommandLine line;
    const Verbs verbs = add_verbs(app, line);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        print_error(fmt::format("command line: {} (see coolaaber-cli --help)", e.what()));
        return exit_bad_input;
    }
    // A closed output pipe is a failed write (exit 1 with a message), not a silent SIGPIPE.
    std::signal(SIGPIPE, SIG_IGN);
    return run_and_print(verbs, line);
}
