// The snooker and three-cushion parts of the CLI (docs/cli.md): `judge` of both games with
// their bad input, and `simulate` with the new tables, ball sets, racks and strike.ball.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli/commands.hpp"
#include "cli/json_in.hpp"
#include "cli_process.hpp"

namespace {

using nlohmann::json;

json ev(const std::string& type, std::initializer_list<int> balls) {
    return {{"type", type}, {"balls", balls}};
}

json snooker_doc() {
    return json::parse(R"({
      "game": "snooker", "options": {"miss_rule": true},
      "state": {"shooter": "A", "on_table": [1, 2, 16, 17, 18, 19, 20, 21], "cue_ball": "on_table",
                "colour_on": false, "nominated": null, "free_ball": false, "respotted_black": false,
                "scores": {"A": 0, "B": 0}, "break": 0, "positions": {"0": [0.7, 0.8]}},
      "events": [{"type": "strike", "balls": [0]}, {"type": "ball_ball", "balls": [0, 1]},
                 {"type": "pocket", "balls": [1], "pocket": "NE"}]})");
}

json carom_doc() {
    return json::parse(R"({
      "game": "three_cushion", "options": {"target": 15, "equal_innings": false},
      "state": {"shooter": "B", "starter": "A", "opening": false, "equalizing": false,
                "scores": {"A": 3, "B": 2}, "innings": {"A": 5, "B": 5}, "run": 0,
                "high_run": {"A": 2, "B": 1}, "positions": {}},
      "events": [{"type": "strike", "balls": [1]}, {"type": "ball_ball", "balls": [1, 2]},
                 {"type": "cushion", "balls": [1]}, {"type": "cushion", "balls": [1]},
                 {"type": "cushion", "balls": [1]}, {"type": "ball_ball", "balls": [1, 0]}]})");
}

std::string bad_path(const json& doc, nlohmann::ordered_json (*verb)(const json&)) {
    try {
        verb(doc);
    } catch (const cli::BadInput& e) {
        return e.path();
    }
    return "";
}

TEST(SnookerJudge, ContractExample) {
    const nlohmann::ordered_json out = cli::judge_command(snooker_doc());
    std::vector<std::string> keys;
    for (const auto& [k, v] : out.items()) keys.push_back(k);
    EXPECT_EQ(keys, (std::vector<std::string>{"foul", "fouls", "foul_points", "points_scored",
                                              "next_shooter", "respotted", "ball_on", "free_ball",
                                              "touching_ball", "miss", "misses",
                                              "may_ask_to_play_again", "frame_over", "winner",
                                              "respotted_black", "scores", "state"}));
    EXPECT_EQ(out["foul"], false);
    EXPECT_EQ(out["points_scored"], 1);
    EXPECT_EQ(out["next_shooter"], "A");
    EXPECT_EQ(out["ball_on"], "colour");
    EXPECT_EQ(out["scores"], json::parse(R"({"A": 1, "B": 0})"));
    EXPECT_EQ(out["state"]["on_table"], json::parse("[2, 16, 17, 18, 19, 20, 21]"));
    EXPECT_EQ(out["state"]["colour_on"], true);
}

TEST(SnookerJudge, FoulWithRespottedColour) {
    json doc = snooker_doc();
    doc["state"]["positions"] = json::object();
    doc["events"] = {ev("strike", {0}),
                     ev("ball_ball", {0, 21}),
                     {{"type", "pocket"}, {"balls", {21}}, {"pocket", "NE"}}};
    const nlohmann::ordered_json out = cli::judge_command(doc);
    EXPECT_EQ(out["fouls"], json::parse(R"(["wrong_ball_first", "ball_not_on_potted"])"));
    EXPECT_EQ(out["foul_points"], 7);
    EXPECT_EQ(out["next_shooter"], "B");
    EXPECT_EQ(out["may_ask_to_play_again"], true);
    ASSERT_EQ(out["respotted"].size(), 1u);
    EXPECT_EQ(out["respotted"][0]["ball"], 21);
    EXPECT_EQ(out["respotted"][0]["spot"], "black");
    EXPECT_NEAR(out["respotted"][0]["pos"][0].get<double>(), 3.569 - 0.324, 1e-12);
}

TEST(CaromJudge, ContractExample) {
    const nlohmann::ordered_json out = cli::judge_command(carom_doc());
    EXPECT_EQ(out["point"], true);
    EXPECT_EQ(out["foul"], false);
    EXPECT_EQ(out["cushions"], 3);
    EXPECT_EQ(out["next_shooter"], "B");
    EXPECT_EQ(out["scores"], json::parse(R"({"A": 3, "B": 3})"));
    EXPECT_EQ(out["innings"], json::parse(R"({"A": 5, "B": 5})"));
    EXPECT_EQ(out["game_over"], false);
    EXPECT_EQ(out["state"]["run"], 1);
}

TEST(CaromJudge, WrongCueBall) {
    json doc = carom_doc();
    doc["events"][0] = ev("strike", {0});
    doc["events"] = {ev("strike", {0}), ev("ball_ball", {0, 2})};
    const nlohmann::ordered_json out = cli::judge_command(doc);
    EXPECT_EQ(out["fouls"], json::parse(R"(["wrong_cue_ball"])"));
    EXPECT_EQ(out["next_shooter"], "A");
    EXPECT_EQ(out["innings"], json::parse(R"({"A": 6, "B": 5})"));
}

struct Bad {
    std::string name;
    json doc;
    std::string path;
};

std::vector<Bad> bad_cases() {
    std::vector<Bad> c;
    auto add = [&](const std::string& name, json base, auto edit, const std::string& path) {
        edit(base);
        c.push_back({name, base, path});
    };
    const json s = snooker_doc(), k = carom_doc();
    add(
        "unknown_game", s, [](json& d) { d["game"] = "snookr"; }, "game");
    add(
        "red_out_of_range", s, [](json& d) { d["state"]["on_table"][0] = 22; },
        "state.on_table[0]");
    add(
        "empty_table", s, [](json& d) { d["state"]["on_table"] = json::array(); },
        "state.on_table");
    add(
        "red_twice", s, [](json& d) { d["state"]["on_table"][1] = 1; }, "state.on_table[1]");
    add(
        "bad_cue_ball", s, [](json& d) { d["state"]["cue_ball"] = "in_hand_kitchen"; },
        "state.cue_ball");
    add(
        "nominated_without_colour_on", s, [](json& d) { d["state"]["nominated"] = 21; },
        "state.nominated");
    add(
        "nominated_red_on_colour", s,
        [](json& d) {
            d["state"]["colour_on"] = true;
            d["state"]["nominated"] = 2;
        },
        "state.nominated");
    add(
        "nominated_off_table", s,
        [](json& d) {
            d["state"]["colour_on"] = true;
            d["state"]["nominated"] = 21;
            d["state"]["on_table"] = {1, 2, 16};
        },
        "state.nominated");
    add(
        "free_ball_without_nomination", s, [](json& d) { d["state"]["free_ball"] = true; },
        "state.free_ball");
    add(
        "respotted_black_with_reds", s, [](json& d) { d["state"]["respotted_black"] = true; },
        "state.respotted_black");
    add(
        "negative_score", s, [](json& d) { d["state"]["scores"]["B"] = -1; }, "state.scores.B");
    add(
        "position_off_table", s,
        [](json& d) {
            d["state"]["positions"]["1"] = {5.0, 0.5};
        },
        "state.positions.1");
    add(
        "position_of_potted_ball", s,
        [](json& d) {
            d["state"]["positions"]["3"] = {1.0, 0.5};
        },
        "state.positions.3");
    add(
        "overlap", s,
        [](json& d) {
            d["state"]["positions"]["1"] = {0.71, 0.8};
        },
        "state.positions.1");
    add(
        "cue_in_hand_outside_the_d", s,
        [](json& d) {
            d["state"]["cue_ball"] = "in_hand";
            d["state"]["positions"]["0"] = {1.5, 0.8};
        },
        "state.positions.0");
    add(
        "event_ball_not_on_table", s,
        [](json& d) {
            d["events"][1] = ev("ball_ball", {0, 5});
        },
        "events[1].balls[1]");
    add(
        "event_unknown_ball", s,
        [](json& d) {
            d["events"][1] = ev("ball_ball", {0, 30});
        },
        "events[1].balls[1]");
    add(
        "strike_on_red", s, [](json& d) { d["events"][0] = ev("strike", {1}); },
        "events[0].balls[0]");
    add(
        "pocket_without_name", s, [](json& d) { d["events"][2].erase("pocket"); },
        "events[2].pocket");
    add(
        "unknown_option", s, [](json& d) { d["options"]["three_miss"] = true; },
        "options.three_miss");
    add(
        "miss_rule_not_bool", s, [](json& d) { d["options"]["miss_rule"] = "on"; },
        "options.miss_rule");
    add(
        "pocketless_table", s, [](json& d) { d["table"] = "carom10ft"; }, "table");
    add(
        "carom_pocket_table", k, [](json& d) { d["table"] = "9ft"; }, "table");
    add(
        "carom_pocket_event", k,
        [](json& d) {
            d["events"][1] = {{"type", "pocket"}, {"balls", {2}}, {"pocket", "N"}};
        },
        "events[1].type");
    add(
        "carom_ball_3", k,
        [](json& d) {
            d["events"][1] = ev("ball_ball", {1, 3});
        },
        "events[1].balls[1]");
    add(
        "carom_score_at_target", k, [](json& d) { d["state"]["scores"]["A"] = 15; },
        "state.scores.A");
    add(
        "carom_target_zero", k, [](json& d) { d["options"]["target"] = 0; }, "options.target");
    add(
        "carom_opening_not_starter", k, [](json& d) { d["state"]["opening"] = true; },
        "state.opening");
    add(
        "carom_equalizing_without_option", k, [](json& d) { d["state"]["equalizing"] = true; },
        "state.equalizing");
    add(
        "carom_unknown_state_field", k, [](json& d) { d["state"]["breaker"] = "A"; },
        "state.breaker");
    add(
        "carom_overlap", k,
        [](json& d) {
            d["state"]["positions"] = {{"0", {1.0, 0.7}}, {"2", {1.02, 0.7}}};
        },
        "state.positions.2");
    return c;
}

class NewGamesBadInput : public ::testing::TestWithParam<Bad> {};

TEST_P(NewGamesBadInput, NamesThePath) {
    EXPECT_EQ(bad_path(GetParam().doc, cli::judge_command), GetParam().path);
}

INSTANTIATE_TEST_SUITE_P(Judge, NewGamesBadInput, ::testing::ValuesIn(bad_cases()),
                         [](const auto& param_info) { return param_info.param.name; });

TEST(NewGamesSimulate, SnookerRackOnItsTable) {
    const nlohmann::ordered_json out = cli::simulate_command(
        json::parse(R"({"table": "snooker12ft", "rack": {"game": "snooker"}})"));
    ASSERT_EQ(out["final"].size(), 22u);
    EXPECT_EQ(out["final"][21]["id"], 21);
    EXPECT_NEAR(out["final"][21]["pos"][0].get<double>(), 3.569 - 0.324, 1e-12);
    EXPECT_EQ(out["events"].size(), 0u);
}

TEST(NewGamesSimulate, CaromRackAndStrikeOnTheYellow) {
    const nlohmann::ordered_json out = cli::simulate_command(json::parse(
        R"({"table": "carom10ft", "rack": {"game": "three_cushion"}, "strike": {"speed": 3, "ball": 1}})"));
    EXPECT_EQ(out["events"][0]["type"], "strike");
    EXPECT_EQ(out["events"][0]["balls"], json::parse("[1]"));
    EXPECT_EQ(out["truncated"], false);
}

TEST(NewGamesSimulate, BallSetByNameAndPreset) {
    const json balls =
        json::parse(R"([{"id": 0, "pos": [0.5, 0.5]}, {"id": 21, "pos": [1.0, 0.5]}])");
    for (const json& params : {json("snooker"), json::parse(R"({"preset": "snooker"})")}) {
        json doc = {
            {"table", "9ft"}, {"params", params}, {"balls", balls}, {"sample_times", {0.0}}};
        const nlohmann::ordered_json out = cli::simulate_command(doc);
        EXPECT_EQ(out["final"].size(), 2u);
    }
    // An unknown set, a bad override, an id beyond 21, a missing struck ball.
    EXPECT_EQ(bad_path(json::parse(R"({"params": "curling", "balls": []})"), cli::simulate_command),
              "params");
    EXPECT_EQ(bad_path(json::parse(R"({"params": {"preset": "pool", "mu_roll": -1}, "balls": []})"),
                       cli::simulate_command),
              "params.mu_roll");
    EXPECT_EQ(bad_path(json::parse(R"({"balls": [{"id": 22, "pos": [0.5, 0.5]}]})"),
                       cli::simulate_command),
              "balls[0].id");
    EXPECT_EQ(
        bad_path(
            json::parse(
                R"({"balls": [{"id": 0, "pos": [0.5, 0.5]}], "strike": {"speed": 1, "ball": 2}})"),
            cli::simulate_command),
        "strike.ball");
}

TEST(NewGamesSimulate, ParamsOverridesKeepTheSet) {
    // mu_roll overridden on the carom set: the balls keep the carom radius.
    const nlohmann::ordered_json out = cli::simulate_command(json::parse(
        R"({"table": "carom10ft", "params": {"preset": "carom", "mu_roll": 0.01},
            "balls": [{"id": 0, "pos": [0.031, 0.031]}]})"));
    EXPECT_EQ(out["final"].size(), 1u);
    EXPECT_EQ(bad_path(json::parse(R"({"table": "carom10ft", "params": {"mu_roll": 0.01},
            "balls": [{"id": 0, "pos": [0.0290, 0.5]}]})"),
                       cli::simulate_command),
              "balls[0].pos");  // carom balls by default on the carom table: R = 0.03075
}

TEST(NewGamesBinary, JudgeSnookerExitCodes) {
    cli_test::CliResult ok = cli_test::run_cli("judge", snooker_doc().dump());
    ASSERT_EQ(ok.status, 0) << ok.err;
    EXPECT_EQ(json::parse(ok.out)["points_scored"], 1);
    json bad = snooker_doc();
    bad["state"]["nominated"] = 21;
    cli_test::CliResult r = cli_test::run_cli("judge", bad.dump());
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(r.out.empty());
    EXPECT_EQ(r.err.rfind("error: state.nominated: ", 0), 0u) << r.err;
}

}  // namespace

namespace {

// simulate's events go into judge unchanged: every field of every event is read.
TEST(NewGamesRoundTrip, SnookerBreakJudged) {
    const nlohmann::ordered_json shot = cli::simulate_command(json::parse(
        R"({"table": "snooker12ft", "rack": {"game": "snooker"},
            "strike": {"speed": 7, "heading_deg": 5, "side": -0.3}})"));
    json positions = json::object();
    json on_table = json::array();
    for (int id = 1; id <= 21; ++id) on_table.push_back(id);
    json doc = {{"game", "snooker"},
                {"state", {{"shooter", "A"}, {"on_table", on_table}, {"cue_ball", "on_table"}}},
                {"events", json::parse(shot["events"].dump())}};
    const nlohmann::ordered_json out = cli::judge_command(doc);
    EXPECT_EQ(out["foul"].get<bool>(), !out["fouls"].empty());
    EXPECT_EQ(out["scores"]["A"].get<int>(), out["points_scored"].get<int>());
    EXPECT_EQ(out["scores"]["B"].get<int>(), out["foul_points"].get<int>());
    EXPECT_GT(out["state"]["positions"].size(), 15u);  // the balls where the shot left them
}

TEST(NewGamesRoundTrip, CaromStrokeOnTheYellowJudged) {
    const nlohmann::ordered_json shot = cli::simulate_command(json::parse(
        R"({"table": "carom10ft", "rack": {"game": "three_cushion"},
            "strike": {"speed": 4, "heading_deg": 60, "side": 0.5, "ball": 1}})"));
    json doc = {
        {"game", "three_cushion"},
        {"state",
         {{"shooter", "B"},
          {"starter", "A"},
          {"opening", false},
          {"positions", {{"0", {0.71, 0.71 - 0.1825}}, {"1", {0.71, 0.71}}, {"2", {2.13, 0.71}}}}}},
        {"events", json::parse(shot["events"].dump())}};
    const nlohmann::ordered_json out = cli::judge_command(doc);
    EXPECT_EQ(out["fouls"], json::array());
    EXPECT_EQ(out["state"]["positions"].size(), 3u);
    EXPECT_NE(out["state"]["positions"]["1"], json::parse("[0.71, 0.71]"));  // the yellow moved
    EXPECT_EQ(out["next_shooter"] == "B", out["point"].get<bool>());
}

}  // namespace
