// `decide` (docs/cli.md): the AI's decision in a position — the output's fields, its
// determinism, calls, ball in hand, choices — and bad input (exit 2, one line naming the JSON
// path, nothing on stdout). Also `match` with ai:LEVEL players.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_process.hpp"

namespace {

using nlohmann::json;

// 9-ball, the 9 alone, straight in to the NE corner from the cue ball.
const std::string kStraight = R"({"game": "9ball", "level": 2, "noise": 0, "seed": 3,
  "state": {"shooter": "A", "breaker": "B", "shot": "normal", "on_table": [9],
            "cue_ball": "on_table", "positions": {"0": [1.6, 0.5], "9": [2.1, 0.9]}}})";

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

TEST(Decide, StrokeForAShot) {
    const json j = decide(kStraight);
    for (const char* key : {"stroke", "call", "cue_pos", "push_out", "choice", "expected_success",
                            "simulations", "seconds"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j.size(), 8u);
    ASSERT_TRUE(j["stroke"].is_object());
    EXPECT_GT(j["stroke"]["speed"].get<double>(), 0.0);
    EXPECT_TRUE(j["call"].is_null()) << "9-ball has no calls";
    EXPECT_TRUE(j["cue_pos"].is_null());
    EXPECT_FALSE(j["push_out"].get<bool>());
    EXPECT_TRUE(j["choice"].is_null());
    EXPECT_GT(j["expected_success"].get<double>(), 0.9);
    EXPECT_GT(j["simulations"].get<int>(), 0);
}

TEST(Decide, SameInputSameDecision) {
    EXPECT_EQ(without_seconds(decide(kStraight)), without_seconds(decide(kStraight)));
}

// docs/cli.md, "General rules": integers may be written as 3 or 3.0.
TEST(Decide, ASeedWrittenWithAFractionPartIsTheSameSeed) {
    std::string with_fraction = kStraight;
    with_fraction.replace(with_fraction.find("\"seed\": 3"), 9, "\"seed\": 3.0");
    EXPECT_EQ(without_seconds(decide(with_fraction)), without_seconds(decide(kStraight)));
}

TEST(Decide, EightBallCallsItsShot) {
    const json j = decide(R"({"game": "8ball", "level": 1, "noise": 1, "seed": 1,
      "state": {"shooter": "A", "breaker": "A", "shot": "normal",
                "groups": {"A": "solids", "B": "stripes"}, "on_table": [3, 8, 12],
                "cue_ball": "on_table",
                "positions": {"0": [1.2, 0.6], "3": [1.8, 0.9], "8": [0.6, 0.3], "12": [2.2, 0.3]}}})");
    ASSERT_TRUE(j["call"].is_object() || j["call"] == "safety") << j.dump();
    if (j["call"].is_object()) {
        EXPECT_EQ(j["call"]["ball"], 3);
    }
}

TEST(Decide, BallInHandOnTheBreak) {
    // A 9-ball rack from `simulate`'s rack would do as well; a few balls suffice here.
    const json j = decide(R"({"game": "9ball", "level": 1, "noise": 1, "seed": 2,
      "state": {"shooter": "A", "breaker": "A", "shot": "break", "on_table": [1, 9],
                "cue_ball": "in_hand_kitchen", "positions": {"1": [1.905, 0.635], "9": [1.9622, 0.635]}}})");
    ASSERT_TRUE(j["cue_pos"].is_array());
    EXPECT_LT(j["cue_pos"][0].get<double>(), 2.54 / 4.0) << "in the kitchen";
    EXPECT_TRUE(j["call"].is_null());
}

TEST(Decide, AnswersAPendingChoice) {
    const json j = decide(R"({"game": "9ball", "level": 3, "seed": 1,
      "choice": {"by": "B", "options": ["shoot", "pass_back"]},
      "state": {"shooter": "B", "breaker": "A", "shot": "after_push_out", "on_table": [1, 9],
                "cue_ball": "on_table", "positions": {"0": [0.5, 0.5], "1": [1.5, 0.6], "9": [2.0, 1.0]}}})");
    ASSERT_TRUE(j["choice"].is_string());
    EXPECT_TRUE(j["choice"] == "shoot" || j["choice"] == "pass_back");
    EXPECT_TRUE(j["stroke"].is_null());
}

TEST(Decide, OddButValidStatesNeverCrash) {
    // A hand-made 9-ball state right after the break with the cue ball in hand; and one with the
    // push-out already declared.
    for (const char* state :
         {R"({"shooter": "A", "breaker": "B", "shot": "after_break", "on_table": [1, 9],
              "cue_ball": "in_hand", "positions": {"1": [1.5, 0.6], "9": [2.0, 1.0]}})",
          R"({"shooter": "A", "breaker": "B", "shot": "push_out", "on_table": [1, 9],
              "cue_ball": "on_table", "positions": {"0": [0.4, 0.4], "1": [1.5, 0.6], "9": [2.0, 1.0]}})"}) {
        const cli_test::CliResult r = cli_test::run_cli(
            "decide", std::string(R"({"game": "9ball", "level": 1, "state": )") + state + "}");
        EXPECT_TRUE(r.status == 0 || r.status == 2) << r.err;
        if (r.status == 0) {
            EXPECT_TRUE(json::parse(r.out)["stroke"].is_object());
        }
    }
}

struct BadCase {
    std::string name, input, path, message;
};

std::ostream& operator<<(std::ostream& os, const BadCase& c) {
    return os << c.name;
}

std::string with(const std::string& fields) {
    return R"({"game": "9ball", "state": {"shooter": "A", "breaker": "A", "shot": "normal",
      "on_table": [9], "cue_ball": "on_table", "positions": {"0": [0.5, 0.5], "9": [1.5, 0.6]}})" +
           std::string(fields.empty() ? "" : ", ") + fields + "}";
}

class DecideBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(DecideBadInput, ExitsTwoNamingThePath) {
    const BadCase& c = GetParam();
    const cli_test::CliResult r = cli_test::run_cli("decide", c.input);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.out, "");
    const std::string prefix = "error: " + c.path + ": ";
    EXPECT_EQ(r.err.substr(0, prefix.size()), prefix) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, DecideBadInput,
    ::testing::Values(
        BadCase{"unparsable", "{", "input", "not valid JSON"},
        BadCase{"unknown_field", with(R"("levels": 3)"), "levels", "unknown field"},
        BadCase{"no_state", R"({"game": "9ball"})", "state", "missing"},
        BadCase{"bad_game", R"({"game": "pool", "state": {}})", "game", "unknown value"},
        BadCase{"level_low", with(R"("level": 0)"), "level", "out of range"},
        BadCase{"level_high", with(R"("level": 6)"), "level", "out of range"},
        BadCase{"level_text", with(R"("level": "5")"), "level", "integer"},
        BadCase{"noise_negative", with(R"("noise": -1)"), "noise", "out of range"},
        BadCase{"seed_negative", with(R"("seed": -1)"), "seed", "whole number"},
        BadCase{"seed_fraction", with(R"("seed": 1.5)"), "seed", "whole number"},
        BadCase{"unbounded_table", with(R"("table": "unbounded")"), "table",
                "cushions and pockets"},
        BadCase{"choice_by", with(R"("choice": {"by": "C", "options": ["shoot"]})"), "choice.by",
                "unknown player"},
        BadCase{"choice_option", with(R"("choice": {"by": "A", "options": ["shoot", "fold"]})"),
                "choice.options[1]", "unknown option"},
        BadCase{"choice_empty", with(R"("choice": {"by": "A", "options": []})"), "choice.options",
                "at least one"},
        BadCase{"choice_twice", with(R"("choice": {"by": "A", "options": ["shoot", "shoot"]})"),
                "choice.options[1]", "twice"},
        BadCase{"missing_position",
                R"({"game": "9ball", "state": {"shooter": "A", "breaker": "A", "shot": "normal",
                  "on_table": [1, 9], "cue_ball": "on_table",
                  "positions": {"0": [0.5, 0.5], "9": [1.5, 0.6]}}})",
                "state.positions", "ball 1 is on the table but has no position"},
        BadCase{"missing_cue",
                R"({"game": "9ball", "state": {"shooter": "A", "breaker": "A", "shot": "normal",
                  "on_table": [9], "cue_ball": "on_table", "positions": {"9": [1.5, 0.6]}}})",
                "state.positions", "cue ball"},
        BadCase{"overlap",
                R"({"game": "9ball", "state": {"shooter": "A", "breaker": "A", "shot": "normal",
                  "on_table": [9], "cue_ball": "on_table",
                  "positions": {"0": [1.5, 0.61], "9": [1.5, 0.6]}}})",
                "state.positions.9", "overlaps ball 0"}),
    [](const ::testing::TestParamInfo<BadCase>& p) { return p.param.name; });

TEST(MatchWithAi, AiAgainstRandomIsReproducible) {
    const std::string args = "match --game 9ball --players ai:1,random --games 2 --seed 4";
    const cli_test::CliResult a = cli_test::run_cli(args), b = cli_test::run_cli(args);
    ASSERT_EQ(a.status, 0) << a.err;
    json ja = json::parse(a.out), jb = json::parse(b.out);
    EXPECT_EQ(ja["players"], json::array({"ai:1", "random"}));
    EXPECT_EQ(
        ja["wins"]["ai:1"].get<int>() + ja["wins"]["random"].get<int>() + ja["capped"].get<int>(),
        2);
    ASSERT_TRUE(ja["decision_seconds"].contains("ai:1"));
    EXPECT_GT(ja["decision_seconds"]["ai:1"]["median"].get<double>(), 0.0);
    for (json* j : {&ja, &jb}) {
        j->erase("seconds");
        j->erase("decision_seconds");
    }
    EXPECT_EQ(ja, jb);
}

TEST(MatchWithAi, DuplicateSwapsTheSides) {
    const cli_test::CliResult r =
        cli_test::run_cli("match --game 8ball --players ai:2,ai:1 --games 2 --seed 9 --duplicate");
    ASSERT_EQ(r.status, 0) << r.err;
    const json j = json::parse(r.out);
    EXPECT_EQ(j["wins"]["ai:2"].get<int>() + j["wins"]["ai:1"].get<int>() + j["capped"].get<int>(),
              2);
}

}  // namespace
