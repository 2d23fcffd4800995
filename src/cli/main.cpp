// coolaaber-cli: the headless interface to the engine (docs/cli.md).
//   coolaaber-cli simulate [FILE] [--pretty]
//   coolaaber-cli judge [FILE] [--pretty]
//   coolaaber-cli decide [FILE] [--pretty]
//   coolaaber-cli bench [--runs N] [--pretty]
//   coolaaber-cli match --game 8ball --players random,random [--games N] [--seed S] [--log FILE]
//                       [--noise X] [--duplicate] [--pretty]
// Exit status: 0 success; 2 bad input (one line on stderr: "error: <json path>: <message>",
// nothing on stdout); 1 internal error.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <new>
#include <sstream>
#include <string>

#include "cli/commands.hpp"
#include "cli/json_in.hpp"
#include "cli/json_out.hpp"

namespace {

constexpr int exit_ok = 0;
constexpr int exit_internal = 1;
constexpr int exit_bad_input = 2;

// One line on stderr: newlines in a message would break the one-line contract.
void print_error(const std::string& message) {
    std::string line = "error: " + message;
    for (char& c : line)
        if (c == '\n' || c == '\r') c = ' ';
    std::fputs((line + "\n").c_str(), stderr);
}

// The input document from FILE, or standard input when FILE is "-".
std::string read_input(const std::string& file) {
    if (file == "-") {
        std::ostringstream text;
        text << std::cin.rdbuf();
        if (std::cin.bad()) throw cli::BadInput("-", "cannot read standard input");
        return text.str();
    }
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec))
        throw cli::BadInput(file, "is a directory: give a JSON file, or - for standard input");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw cli::BadInput(file, "cannot open the file: check its name and permissions");
    std::string text;
    try {
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    } catch (const std::exception& e) {
        throw cli::BadInput(file, fmt::format("cannot read the file ({})", e.what()));
    }
    if (in.bad()) throw cli::BadInput(file, "cannot read the file");
    return text;
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

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "coolaaber-cli: the Coolaaber pool engine without a window. Reads one JSON "
        "document, writes one JSON document (docs/cli.md).",
        "coolaaber-cli"};
    app.require_subcommand(1);
    app.fallthrough();

    std::string file = "-";
    bool pretty = false;
    std::int64_t runs = cli::default_bench_runs;

    CLI::App* simulate =
        app.add_subcommand("simulate", "Simulate one shot: balls, a strike → events");
    CLI::App* judge = app.add_subcommand("judge", "Apply the rules of a game to one shot's events");
    CLI::App* decide = app.add_subcommand("decide", "The computer player's decision in a position");
    CLI::App* bench = app.add_subcommand("bench", "Time the standard scenes");
    cli::MatchOptions match_options;
    CLI::App* match = app.add_subcommand("match", "Play whole games between two players");
    match->add_option("--game", match_options.game, "8ball or 9ball")->capture_default_str();
    match->add_option("--players", match_options.players, "Two players: random, ai:LEVEL")
        ->capture_default_str();
    match->add_option("--games", match_options.games, "Games to play")->capture_default_str();
    match->add_option("--seed", match_options.seed, "Seed of the racks and the players")
        ->capture_default_str();
    match->add_option("--log", match_options.log, "Write one JSON line per shot to FILE");
    match->add_option("--noise", match_options.noise, "Scale of the execution noise")
        ->capture_default_str();
    match->add_flag("--duplicate", match_options.duplicate,
                    "Play each seed twice, the sides swapped");
    for (CLI::App* verb : {simulate, judge, decide})
        verb->add_option("FILE", file, "Input JSON document; - or absent: standard input");
    bench->add_option("--runs", runs, "Simulations per scene")->capture_default_str();
    for (CLI::App* a : {&app, simulate, judge, decide, bench, match})
        a->add_flag("--pretty", pretty, "Indent the output (default: one line)");

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

    try {
        std::string text;
        if (simulate->parsed()) {
            nlohmann::ordered_json out =
                cli::simulate_command(cli::parse_document(read_input(file)));
            text = cli::write_document(out, pretty);
        } else if (judge->parsed()) {
            nlohmann::ordered_json out = cli::judge_command(cli::parse_document(read_input(file)));
            text = cli::write_document(out, pretty);
        } else if (decide->parsed()) {
            nlohmann::ordered_json out = cli::decide_command(cli::parse_document(read_input(file)));
            text = cli::write_document(out, pretty);
        } else if (bench->parsed()) {
            nlohmann::ordered_json out = cli::bench_command(runs);
            text = cli::write_document(out, pretty);
        } else if (match->parsed()) {
            nlohmann::ordered_json out = cli::match_command(match_options);
            text = cli::write_document(out, pretty);
        }
        return print_document(text);
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
