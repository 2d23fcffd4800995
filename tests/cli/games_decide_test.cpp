// `decide` and `match` for snooker and three-cushion (docs/cli.md, "decide: snooker and
// three-cushion", "match: snooker and three-cushion"): the output's fields, determinism, the
// nomination and the cue ball in the D, the choice after a foul, whole matches, bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_process.hpp"

namespace {

using nlohmann::json;

// A red on in the middle of the table, the colours on their spots, the cue ball in the D.
const std::string kSnookerInHand = R"({"game": "snooker", "level": 2, "seed": 5,
  "state": {"shooter": "A", "on_table": [1, 16, 17, 18, 19, 20, 21], "cue_ball": "in_hand",
    "positions": {"1": [2.2, 0.6], "16": [0.737, 0.597], "17": [0.737, 1.181],
                  "18": [0.737, 0.889], "19": [1.7845, 0.889], "20": [2.67675, 0.889],
                  "21": [3.245, 0.889]}}})";

// A colour on after a red, the cue ball near the blue.
const std::string kSnookerColour = R"({"game": "snooker", "level": 3, "seed": 2,
  "state": {"shooter": "B", "on_table": [2, 16, 17, 18, 19, 20, 21], "cue_ball": "on_table",
    "colour_on": true, "scores": {"A": 0, "B": 1}, "break": 1,
    "positions": {"0": [1.6, 0.7], "2": [3.0, 1.5], "16": [0.737, 0.597], "17": [0.737, 1.181],
                  "18": [0.737, 0.889], "19": [1.7845, 0.889], "20": [2.67675, 0.889],
                  "21": [3.245, 0.889]}}})";

const std::string kOpening = R"({"game": "three_cushion", "level": 3, "seed": 9,
  "state": {"shooter": "A", "positions": {"0": [0.71, 0.5275], "1": [0.71, 0.71],
                                          "2": [2.13, 0.71]}}})";

json decide(const std::string& input) {
    const cli_test::CliResult r = cli_test::run_cli("decide", input);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    return json::parse(r.out);
}

json without_seconds(json j) {
    j.erase("seconds");
    return j;
}

TEST(DecideSnooker, PlacesTheCueBallInTheD) {
    const json j = decide(kSnookerInHand);
    for (const char* key : {"stroke", "nominated", "cue_pos", "kind", "expected_success",
                            "expected_value", "simulations", "seconds"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j.size(), 8u);
    EXPECT_TRUE(j["nominated"].is_null()) << "a red is on";
    ASSERT_TRUE(j["cue_pos"].is_array());
    const double x = j["cue_pos"][0], y = j["cue_pos"][1];
    // The D: behind the baulk line (x 0.737), within 0.292 m of its centre (0.737, 0.889).
    EXPECT_LE(x, 0.737);
    EXPECT_LE(std::hypot(x - 0.737, y - 0.889), 0.292);
    EXPECT_GT(j["stroke"]["speed"].get<double>(), 0.0);
    EXPECT_GT(j["simulations"].get<int>(), 0);
    EXPECT_EQ(without_seconds(j), without_seconds(decide(kSnookerInHand)));
}

TEST(DecideSnooker, NominatesAColourWhenAColourIsOn) {
    const json j = decide(kSnookerColour);
    ASSERT_TRUE(j["nominated"].is_number_integer());
    EXPECT_GE(j["nominated"].get<int>(), 16);
    EXPECT_LE(j["nominated"].get<int>(), 21);
    EXPECT_TRUE(j["cue_pos"].is_null());
}

TEST(DecideSnooker, ChoosesAfterAFoul) {
    // The state after A's foul (B to play), and the state A played from.
    const json j = decide(R"({"game": "snooker", "level": 5,
      "state": {"shooter": "B", "on_table": [1, 21], "cue_ball": "on_table", "scores": {"A": 0, "B": 4},
                "positions": {"0": [1.0, 0.3], "1": [3.3, 1.6], "21": [3.245, 0.889]}},
      "after_foul": {"miss": true, "misses": 1,
        "before": {"shooter": "A", "on_table": [1, 21], "cue_ball": "on_table",
                   "positions": {"0": [1.0, 0.3], "1": [3.3, 1.6], "21": [3.245, 0.889]}}}})");
    ASSERT_TRUE(j.contains("after_foul"));
    const std::vector<std::string> open{"play", "play_again", "replace"};
    EXPECT_NE(std::find(open.begin(), open.end(), j["after_foul"].get<std::string>()), open.end());
}

TEST(DecideThreeCushion, StrikesTheShootersBallReproducibly) {
    const json j = decide(kOpening);
    for (const char* key :
         {"stroke", "expected_success", "expected_value", "simulations", "seconds"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j["stroke"]["ball"], 0);
    EXPECT_EQ(without_seconds(j), without_seconds(decide(kOpening)));
    std::string yellow = kOpening;
    yellow.replace(yellow.find("\"shooter\": \"A\""), 14,
                   R"("shooter": "B", "starter": "A", "opening": false)");
    EXPECT_EQ(decide(yellow)["stroke"]["ball"], 1) << "B plays the yellow";
}

struct BadCase {
    std::string name, input, path, message;
};

std::ostream& operator<<(std::ostream& os, const BadCase& c) {
    return os << c.name;
}

class DecideGamesBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(DecideGamesBadInput, ExitsTwoNamingThePath) {
    const BadCase& c = GetParam();
    const cli_test::CliResult r = cli_test::run_cli("decide", c.input);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.out, "");
    const std::string prefix = "error: " + c.path + ": ";
    EXPECT_EQ(r.err.substr(0, prefix.size()), prefix) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, DecideGamesBadInput,
    ::testing::Values(
        BadCase{"snooker_level", R"({"game": "snooker", "level": 6, "state": {"shooter": "A",
                "on_table": [21], "cue_ball": "in_hand", "positions": {"21": [3.2, 0.9]}}})",
                "level", "out of range"},
        BadCase{"snooker_position", R"({"game": "snooker", "state": {"shooter": "A",
                "on_table": [1, 21], "cue_ball": "in_hand", "positions": {"21": [3.2, 0.9]}}})",
                "state.positions", "ball 1"},
        BadCase{"snooker_pocketless", R"({"game": "snooker", "table": "carom10ft", "state":
                {"shooter": "A", "on_table": [21], "cue_ball": "in_hand"}})",
                "table", "pockets"},
        BadCase{"after_foul_same_shooter", R"({"game": "snooker", "state": {"shooter": "A",
                "on_table": [21], "cue_ball": "on_table", "positions": {"0": [1, 1],
                "21": [3.2, 0.9]}}, "after_foul": {"before": {"shooter": "A", "on_table": [21],
                "cue_ball": "on_table", "positions": {"0": [1, 1], "21": [3.2, 0.9]}}}})",
                "after_foul.before.shooter", "offender"},
        BadCase{"pool_after_foul", R"({"game": "9ball", "after_foul": {}, "state": {}})",
                "after_foul", "snooker"},
        BadCase{"carom_positions", R"({"game": "three_cushion", "state": {"shooter": "A",
                "positions": {"0": [0.7, 0.5]}}})",
                "state.positions", "three balls"},
        BadCase{"carom_pockets", R"({"game": "three_cushion", "table": "9ft", "state":
                {"shooter": "A"}})",
                "table", "no pockets"}));

json summary(const std::string& args) {
    const cli_test::CliResult r = cli_test::run_cli("match " + args);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    return json::parse(r.out);
}

TEST(MatchGames, SnookerFramesBetweenTwoLevels) {
    const json j = summary("--game snooker --players ai:2,ai:1 --games 2 --duplicate --reds 2");
    EXPECT_EQ(j["reds"], 2);
    EXPECT_EQ(j["capped"], 0);
    const json& r = j["results"];
    ASSERT_TRUE(r.contains("ai:1") && r.contains("ai:2"));
    EXPECT_EQ(r["ai:1"]["wins"].get<int>() + r["ai:2"]["wins"].get<int>(), 2);
    EXPECT_GE(r["ai:2"]["highest_break"].get<int>(), 0);
    EXPECT_GT(j["strokes"].get<int>(), 0);
}

TEST(MatchGames, ThreeCushionGamesAreReproducible) {
    const std::string args = "--game three_cushion --players ai:1,ai:1 --games 2 --target 1";
    json a = summary(args), b = summary(args);
    for (json* j : {&a, &b}) {
        j->erase("seconds");
        for (auto& [k, v] : (*j)["results"].items()) v.erase("decision_seconds");
    }
    EXPECT_EQ(a, b);
    EXPECT_EQ(a["target"], 1);
    EXPECT_EQ(a["results"]["A"]["wins"].get<int>() + a["results"]["B"]["wins"].get<int>(), 2);
}

TEST(MatchGames, BadCommandLines) {
    struct Case {
        std::string args, option, message;
    };
    const std::vector<Case> cases = {
        {"--game snooker", "--players", "computer players only"},
        {"--game snooker --players ai:1,ai:2 --reds 16", "--reds", "out of range"},
        {"--game snooker --players ai:1,ai:2 --target 3", "--target", "three_cushion"},
        {"--game three_cushion --players ai:1,ai:2 --reds 3", "--reds", "snooker"},
        {"--game 8ball --reds 3", "--reds", "snooker"},
        {"--game 9ball --target 3", "--target", "three_cushion"},
    };
    for (const Case& c : cases) {
        const cli_test::CliResult r = cli_test::run_cli("match " + c.args);
        EXPECT_EQ(r.status, 2) << c.args;
        EXPECT_EQ(r.out, "") << c.args;
        EXPECT_EQ(r.err.rfind("error: " + c.option + ": ", 0), 0u) << c.args << ": " << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    }
}

}  // namespace
