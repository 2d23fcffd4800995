// `match` (docs/cli.md): the summary, determinism, the per-shot log, --duplicate, and bad
// command lines (exit 2, one line naming the option).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli/commands.hpp"
#include "cli/json_in.hpp"
#include "cli_process.hpp"

namespace {

using nlohmann::json;

json summary(const std::string& args) {
    const cli_test::CliResult r = cli_test::run_cli("match " + args);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    return json::parse(r.out);
}

// The summary without the timings, which differ from run to run.
json without_timings(json j) {
    j.erase("seconds");
    j.erase("decision_seconds");
    return j;
}

TEST(Match, SummaryOfRandomEightBallGames) {
    const json j = summary("--game 8ball --players random,random --games 20 --seed 1");
    EXPECT_EQ(j["game"], "8ball");
    EXPECT_EQ(j["games"], 20);
    EXPECT_EQ(j["players"], json::array({"random", "random"}));
    // Both players are of one kind: wins by seat.
    ASSERT_TRUE(j["wins"].contains("A"));
    ASSERT_TRUE(j["wins"].contains("B"));
    EXPECT_EQ(j["wins"].size(), 2u);
    EXPECT_EQ(j["wins"]["A"].get<int>() + j["wins"]["B"].get<int>() + j["capped"].get<int>(), 20);
    EXPECT_EQ(j["capped_games"].size(), j["capped"].get<std::size_t>());
    EXPECT_GT(j["shots"].get<int>(), 20);
    EXPECT_GT(j["fouls"].get<int>(), 0);
    EXPECT_LE(j["fouls"].get<int>(), j["shots"].get<int>());
    EXPECT_GE(j["break_and_runs"].get<int>(), 0);
    EXPECT_GE(j["stalemates"].get<int>(), 0);
    EXPECT_GE(j["seconds"].get<double>(), 0.0);
    for (const char* seat : {"A", "B"}) {
        EXPECT_GE(j["decision_seconds"][seat]["median"].get<double>(), 0.0);
        EXPECT_GE(j["decision_seconds"][seat]["p95"].get<double>(),
                  j["decision_seconds"][seat]["median"].get<double>());
    }
}

TEST(Match, DeterministicFromTheSeed) {
    const std::string args = "--game 9ball --players random,random --games 30 --seed 5";
    EXPECT_EQ(without_timings(summary(args)), without_timings(summary(args)));
    EXPECT_NE(without_timings(summary(args)),
              without_timings(summary("--game 9ball --games 30 --seed 6")));
}

TEST(Match, NoiseZeroAndDuplicate) {
    const json quiet = summary("--game 8ball --games 4 --seed 2 --noise 0");
    EXPECT_EQ(quiet["games"], 4);
    const json dup = summary("--game 8ball --games 6 --seed 2 --duplicate");
    EXPECT_EQ(dup["games"], 6);
    EXPECT_EQ(dup["wins"]["A"].get<int>() + dup["wins"]["B"].get<int>() + dup["capped"].get<int>(),
              6);
}

TEST(Match, LogHasOneLinePerShot) {
    const std::filesystem::path log = cli_test::temp_path("match-log");
    const json j = summary("--game 8ball --games 3 --seed 3 --log '" + log.string() + "'");
    std::ifstream in(log);
    std::string line;
    int lines = 0, last_shot = 0, last_game = -1;
    while (std::getline(in, line)) {
        const json shot = json::parse(line);
        for (const char* key : {"game", "shot", "seat", "player", "state", "stroke", "call",
                                "push_out", "events", "verdict", "choice"})
            EXPECT_TRUE(shot.contains(key)) << key;
        EXPECT_EQ(shot["player"], "random");
        EXPECT_FALSE(shot["events"].empty());
        EXPECT_EQ(shot["events"][0]["type"], "strike");
        EXPECT_TRUE(shot["verdict"].contains("state"));
        EXPECT_TRUE(shot["state"]["positions"].contains("0"));  // the cue ball, placed
        if (shot["game"] != last_game) {
            last_game = shot["game"];
            last_shot = 0;
            EXPECT_EQ(shot["state"]["shot"], "break");
        }
        EXPECT_EQ(shot["shot"], ++last_shot);
        // A choice offered is recorded with the option taken.
        if (!shot["verdict"]["choice"].is_null()) {
            EXPECT_TRUE(shot["choice"].is_string());
        }
        ++lines;
    }
    EXPECT_EQ(lines, j["shots"].get<int>());
    std::filesystem::remove(log);
}

TEST(Match, BadCommandLines) {
    struct Case {
        std::string args, option, message;
    };
    const std::vector<Case> cases = {
        {"--players ai:0,random", "--players", "ai:1 to ai:5"},
        {"--players random,ai:35", "--players", "ai:1 to ai:5"},
        {"--players ai:,random", "--players", "ai:1 to ai:5"},
        {"--players ai:9,random", "--players", "ai:1 to ai:5"},
        {"--players random", "--players", "two players"},
        {"--players random,human", "--players", "unknown player"},
        {"--game pool", "--game", "unknown game"},
        {"--games 0", "--games", "out of range"},
        {"--games 3 --duplicate", "--games", "even"},
        {"--noise -1", "--noise", "out of range"},
        {"--seed -3", "--seed", "whole number"},
        {"--seed 18446744073709551616", "--seed", "whole number"},
        {"--log /nonexistent-dir/x.jsonl", "--log", "cannot write"},
        {"--bogus", "command line", ""},
    };
    for (const Case& c : cases) {
        const cli_test::CliResult r = cli_test::run_cli("match " + c.args);
        EXPECT_EQ(r.status, 2) << c.args;
        EXPECT_EQ(r.out, "") << c.args;
        EXPECT_EQ(r.err.rfind("error: " + c.option + ": ", 0), 0u) << c.args << ": " << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

TEST(Match, CommandFunctionThrowsBadInput) {
    cli::MatchOptions o;
    o.players = "ai:6,ai:5";
    try {
        cli::match_command(o);
        FAIL();
    } catch (const cli::BadInput& e) {
        EXPECT_EQ(e.path(), "--players");
    }
    o = {};
    o.games = 2;
    const nlohmann::ordered_json out = cli::match_command(o);
    EXPECT_EQ(out["games"], 2);
}

}  // namespace
