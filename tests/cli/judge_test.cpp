// `judge` (docs/cli.md): valid documents, every kind of bad input with its JSON path, and
// the binary's exit status and one-line error.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/json_in.hpp"
#include "cli/rules_json.hpp"
#include "cli_process.hpp"
#include "physics/table.hpp"

namespace {

using nlohmann::json;

// The contract's example input.
json contract_example() {
    return json::parse(R"({
      "game": "8ball",
      "table": "9ft",
      "options": { "call_shots": "all", "scratch_on_eight_loses": false },
      "state": {
        "shooter": "A", "breaker": "A", "shot": "break",
        "groups": null,
        "on_table": [1,2,3,4,5,6,7,8,9,10,11,12,13,14,15],
        "cue_ball": "in_hand_kitchen",
        "call": null,
        "fouls_in_row": { "A": 0, "B": 0 },
        "warned": { "A": false, "B": false },
        "positions": { "0": [0.5, 0.6], "1": [1.905, 0.635] }
      },
      "events": [ { "type": "ball_ball", "balls": [0, 1] },
                  { "type": "pocket", "balls": [3], "pocket": "NE" } ]
    })");
}

// 8-ball, A has solids, after the break, the cue ball on the table.
json eight_ball_groups() {
    json doc = contract_example();
    doc["state"]["shot"] = "normal";
    doc["state"]["cue_ball"] = "on_table";
    doc["state"]["groups"] = {{"A", "solids"}, {"B", "stripes"}};
    doc["state"]["call"] = {{"ball", 3}, {"pocket", "SW"}};
    doc["state"]["positions"] = json::object();
    doc["events"] = json::array();
    return doc;
}

json nine_ball() {
    return json::parse(R"({
      "game": "9ball",
      "state": { "shooter": "A", "breaker": "B", "shot": "normal",
                 "on_table": [1,2,3,4,5,6,7,8,9], "cue_ball": "on_table" },
      "events": []
    })");
}

json ev(const std::string& type, std::vector<int> balls) {
    return {{"type", type}, {"balls", balls}};
}
json pot(int ball, const std::string& pocket) {
    json e = ev("pocket", {ball});
    e["pocket"] = pocket;
    return e;
}

// The path of the BadInput the document raises ("" if none).
std::string bad_path(const json& doc) {
    try {
        cli::judge_command(doc);
    } catch (const cli::BadInput& e) {
        return e.path();
    }
    return "";
}

TEST(JudgeCommand, ContractExample) {
    json out = cli::judge_command(contract_example());
    EXPECT_EQ(out["foul"], false);
    EXPECT_EQ(out["fouls"], json::array());
    EXPECT_EQ(out["turn_passes"], false);
    EXPECT_EQ(out["next_shooter"], "A");
    EXPECT_EQ(out["ball_in_hand"], "none");
    EXPECT_EQ(out["groups"], nullptr);
    EXPECT_EQ(out["respot"], json::array());
    EXPECT_EQ(out["choice"], nullptr);
    EXPECT_EQ(out["game_over"], false);
    EXPECT_EQ(out["winner"], nullptr);
    EXPECT_EQ(out["break"], "legal");
    const json& s = out["state"];
    EXPECT_EQ(s["shooter"], "A");
    EXPECT_EQ(s["shot"], "normal");
    EXPECT_EQ(s["cue_ball"], "on_table");
    EXPECT_EQ(s["on_table"].size(), 14u);
    EXPECT_EQ(s["positions"]["1"], json::array({1.905, 0.635}));
}

TEST(JudgeCommand, OutputFieldsInTheContractsOrder) {
    const json doc = contract_example();
    cli::JsonIn in(doc, "");
    physics::Table table = physics::build_table(*physics::table_preset("9ft"));
    rules::GameState s = cli::read_state(in.at("state"), rules::Game::eight_ball, table, {});
    rules::Verdict v;
    v.state = s;
    std::vector<std::string> keys;
    const nlohmann::ordered_json verdict = cli::to_json(v);
    for (const auto& [k, _] : verdict.items()) keys.push_back(k);
    EXPECT_EQ(keys, (std::vector<std::string>{"foul", "fouls", "turn_passes", "next_shooter",
                                              "ball_in_hand", "groups", "respot", "choice",
                                              "game_over", "winner", "break", "state"}));
    keys.clear();
    const nlohmann::ordered_json state = cli::to_json(s);
    for (const auto& [k, _] : state.items()) keys.push_back(k);
    EXPECT_EQ(keys, (std::vector<std::string>{"shooter", "breaker", "shot", "groups", "on_table",
                                              "cue_ball", "call", "fouls_in_row", "warned",
                                              "positions"}));
}

TEST(JudgeCommand, StateRoundTrips) {
    json doc = eight_ball_groups();
    doc["state"]["fouls_in_row"] = {{"A", 1}, {"B", 2}};
    doc["state"]["warned"] = {{"A", true}, {"B", false}};
    doc["state"]["call"] = "safety";
    doc["state"]["positions"] = {{"0", {0.7, 0.3}}, {"3", {1.2, 0.5}}};
    cli::JsonIn in(doc, "");
    physics::Table table = physics::build_table(*physics::table_preset("9ft"));
    rules::GameState s = cli::read_state(in.at("state"), rules::Game::eight_ball, table, {});
    json written = cli::to_json(s);
    EXPECT_EQ(written, doc["state"]);
}

TEST(JudgeCommand, NextStateIsValidInput) {
    json doc = eight_ball_groups();
    doc["events"] = {ev("ball_ball", {0, 3}), pot(3, "SW")};
    json out = cli::judge_command(doc);
    EXPECT_EQ(out["next_shooter"], "A");
    json again = doc;
    again["state"] = out["state"];
    again["events"] = {ev("ball_ball", {0, 4}), ev("cushion", {4})};
    json second = cli::judge_command(again);
    EXPECT_EQ(second["next_shooter"], "B");
    EXPECT_EQ(second["turn_passes"], true);
}

TEST(JudgeCommand, FoulsInCanonicalOrder) {
    json doc = eight_ball_groups();
    doc["events"] = {ev("ball_ball", {0, 11}), ev("ball_ball", {11, 12}), ev("off_table", {12}),
                     pot(0, "SW")};
    json out = cli::judge_command(doc);
    EXPECT_EQ(out["foul"], true);
    EXPECT_EQ(out["fouls"], json::parse(R"(["scratch", "wrong_ball_first",
                                            "no_rail_after_contact", "ball_off_table"])"));
    EXPECT_EQ(out["ball_in_hand"], "anywhere");
    EXPECT_EQ(out["state"]["cue_ball"], "in_hand");
}

TEST(JudgeCommand, IllegalBreakChoice) {
    json doc = contract_example();
    doc["events"] = {ev("ball_ball", {0, 1}), ev("cushion", {1})};
    json out = cli::judge_command(doc);
    EXPECT_EQ(out["break"], "illegal");
    EXPECT_EQ(out["foul"], false);
    EXPECT_EQ(out["next_shooter"], nullptr);
    EXPECT_EQ(out["turn_passes"], true);
    EXPECT_EQ(out["choice"], json::parse(R"({"by": "B", "options": ["accept_table",
        "rerack_and_break", "rerack_offender_breaks"]})"));
}

TEST(JudgeCommand, EightBallWin) {
    json doc = eight_ball_groups();
    doc["state"]["on_table"] = {8, 9, 10};
    doc["state"]["call"] = {{"ball", 8}, {"pocket", "NE"}};
    doc["events"] = {ev("ball_ball", {0, 8}), pot(8, "NE")};
    json out = cli::judge_command(doc);
    EXPECT_EQ(out["game_over"], true);
    EXPECT_EQ(out["winner"], "A");
    EXPECT_EQ(out["next_shooter"], nullptr);
    EXPECT_EQ(out["turn_passes"], false);
    EXPECT_EQ(out["groups"], json::parse(R"({"A": "solids", "B": "stripes"})"));
}

TEST(JudgeCommand, OptionsChangeTheVerdict) {
    json doc = eight_ball_groups();
    doc["events"] = {ev("ball_ball", {0, 3})};
    EXPECT_EQ(cli::judge_command(doc)["fouls"], json::array({"no_rail_after_contact"}));
    doc["options"] = {{"rail_after_contact", false}, {"foul_ball_in_hand", "kitchen"},
                      {"call_shots", "none"},        {"eight_on_break", "wins"},
                      {"groups_on_break", true},     {"scratch_on_eight_loses", true}};
    EXPECT_EQ(cli::judge_command(doc)["fouls"], json::array());
}

TEST(JudgeCommand, NineBallPushOut) {
    json doc = nine_ball();
    doc["state"]["shot"] = "push_out";
    doc["events"] = {ev("ball_ball", {0, 9}), pot(9, "N")};
    json out = cli::judge_command(doc);
    EXPECT_EQ(out["choice"], json::parse(R"({"by": "B", "options": ["shoot", "pass_back"]})"));
    EXPECT_EQ(out["respot"], json::array({9}));
    EXPECT_EQ(out["next_shooter"], nullptr);
    EXPECT_EQ(out["state"]["shot"], "after_push_out");
    EXPECT_EQ(out["state"]["shooter"], "B");
    EXPECT_EQ(out["state"]["positions"]["9"], json::array({1.905, 0.635}));
}

TEST(JudgeCommand, NineBallThirdFoul) {
    json doc = nine_ball();
    doc["state"]["fouls_in_row"] = {{"A", 2}, {"B", 0}};
    doc["state"]["warned"] = {{"A", true}, {"B", false}};
    doc["events"] = {ev("cushion", {0})};
    json out = cli::judge_command(doc);
    EXPECT_EQ(out["fouls"], json::array({"no_contact", "third_consecutive_foul"}));
    EXPECT_EQ(out["winner"], "B");
    EXPECT_EQ(out["turn_passes"], true);
    EXPECT_EQ(out["ball_in_hand"], "none");
}

TEST(JudgeCommand, AcceptsSimulateEvents) {
    json doc = nine_ball();
    doc["events"] = json::parse(R"([
      { "time": 0.0, "type": "strike", "balls": [0], "pos": [[0.635, 0.635]], "vel": [[3.1, 0]],
        "spin": [[0, 0, 0]] },
      { "time": 0.29, "type": "transition", "balls": [0], "from": "sliding", "to": "rolling",
        "pos": [[1.3, 0.635]], "vel": [[2.2, 0]], "spin": [[0, 77.0, 0]] },
      { "time": 0.81, "type": "ball_ball", "balls": [0, 1], "speed": 1.02,
        "pos": [[1.848, 0.62], [1.905, 0.635]], "vel": [[0.1, -0.3], [0.9, 0.3]],
        "spin": [[0, 70.1, 0], [0, 0, 0]] },
      { "time": 1.2, "type": "cushion", "balls": [1], "cushion": "N-NE", "speed": 0.8,
        "pos": [[2.2, 1.2414]], "vel": [[0.8, -0.5]], "spin": [[3.0, 20.0, 0]] },
      { "time": 1.5, "type": "cushion", "balls": [1], "pocket_jaw": "NE", "speed": 0.3,
        "pos": [[2.45, 1.2]], "vel": [[0.2, 0.1]], "spin": [[0, 0, 0]] },
      { "time": 1.9, "type": "pocket", "balls": [1], "pocket": "NE",
        "pos": [[2.52, 1.25]], "vel": [[0, 0]], "spin": [[0, 0, 0]] },
      { "time": 2.5, "type": "transition", "balls": [0], "from": "rolling", "to": "stationary",
        "pos": [[1.9, 0.6]], "vel": [[0, 0]], "spin": [[0, 0, 0]] }
    ])");
    json out = cli::judge_command(doc);
    EXPECT_EQ(out["foul"], false);
    EXPECT_EQ(out["next_shooter"], "A");
    EXPECT_EQ(out["state"]["positions"]["0"], json::array({1.9, 0.6}));
    EXPECT_FALSE(out["state"]["positions"].contains("1"));
}

TEST(JudgeCommand, TableSetsTheHeadString) {
    // Ball 2 at x = 0.55: in the kitchen of a 9 ft table (L/4 = 0.635), not of a 7 ft (0.4953).
    json doc = eight_ball_groups();
    doc["state"]["cue_ball"] = "in_hand_kitchen";
    doc["state"]["positions"] = {{"0", {0.3, 0.45}}, {"2", {0.55, 0.45}}};
    doc["events"] = {ev("ball_ball", {0, 2}), ev("cushion", {2})};
    EXPECT_EQ(cli::judge_command(doc)["fouls"], json::array({"bad_play_from_kitchen"}));
    doc["table"] = "7ft";
    EXPECT_EQ(cli::judge_command(doc)["fouls"], json::array());
}

struct BadCase {
    std::string name;
    json doc;
    std::string path;
};

// gtest prints a parameter with this (the case's name, not its bytes).
std::ostream& operator<<(std::ostream& os, const BadCase& c) {
    return os << c.name;
}

std::vector<BadCase> bad_cases() {
    std::vector<BadCase> cases;
    auto add = [&](std::string name, json base, auto edit, std::string path) {
        edit(base);
        cases.push_back({std::move(name), std::move(base), std::move(path)});
    };
    const json e8 = eight_ball_groups(), brk = contract_example(), n9 = nine_ball();
    add(
        "unknown_top_level_field", e8, [](json& d) { d["gmae"] = "8ball"; }, "gmae");
    add(
        "unknown_game", e8, [](json& d) { d["game"] = "10ball"; }, "game");
    add(
        "missing_events", e8, [](json& d) { d.erase("events"); }, "events");
    add(
        "unknown_table", e8, [](json& d) { d["table"] = "6ft"; }, "table");
    add(
        "unknown_option", e8,
        [](json& d) {
            d["options"] = {{"call_shot", "all"}};
        },
        "options.call_shot");
    add(
        "unknown_option_value", e8,
        [](json& d) {
            d["options"] = {{"call_shots", "some"}};
        },
        "options.call_shots");
    add(
        "option_boolean_as_string", e8,
        [](json& d) {
            d["options"] = {{"scratch_on_eight_loses", "true"}};
        },
        "options.scratch_on_eight_loses");
    add(
        "eight_on_break_as_boolean", e8,
        [](json& d) {
            d["options"] = {{"eight_on_break", true}};
        },
        "options.eight_on_break");
    add(
        "unknown_state_field", e8, [](json& d) { d["state"]["shooterr"] = "A"; }, "state.shooterr");
    add(
        "missing_shooter", e8, [](json& d) { d["state"].erase("shooter"); }, "state.shooter");
    add(
        "unknown_player", e8, [](json& d) { d["state"]["shooter"] = "C"; }, "state.shooter");
    add(
        "unknown_shot", e8, [](json& d) { d["state"]["shot"] = "jump"; }, "state.shot");
    add(
        "cue_ball_listed_on_table", e8,
        [](json& d) {
            d["state"]["on_table"] = {0, 8};
        },
        "state.on_table[0]");
    add(
        "ball_listed_twice", e8,
        [](json& d) {
            d["state"]["on_table"] = {8, 8};
        },
        "state.on_table[1]");
    add(
        "eight_not_on_table", e8,
        [](json& d) {
            d["state"]["on_table"] = {1, 2};
        },
        "state.on_table");
    add(
        "nine_ball_with_ball_twelve", n9,
        [](json& d) {
            d["state"]["on_table"] = {9, 12};
        },
        "state.on_table[1]");
    add(
        "same_groups", e8, [](json& d) { d["state"]["groups"]["B"] = "solids"; }, "state.groups");
    add(
        "groups_in_nine_ball", n9,
        [](json& d) {
            d["state"]["groups"] = {{"A", "solids"}, {"B", "stripes"}};
        },
        "state.groups");
    add(
        "groups_on_the_break", brk,
        [](json& d) {
            d["state"]["groups"] = {{"A", "solids"}, {"B", "stripes"}};
        },
        "state.groups");
    add(
        "break_without_kitchen_ball_in_hand", brk,
        [](json& d) { d["state"]["cue_ball"] = "on_table"; }, "state.cue_ball");
    add(
        "negative_foul_count", e8,
        [](json& d) {
            d["state"]["fouls_in_row"] = {{"A", -1}, {"B", 0}};
        },
        "state.fouls_in_row.A");
    add(
        "warned_missing_player", e8,
        [](json& d) {
            d["state"]["warned"] = {{"A", true}};
        },
        "state.warned.B");
    add(
        "call_of_ball_not_on_table", e8,
        [](json& d) {
            d["state"]["on_table"] = {1, 8};
        },
        "state.call.ball");
    add(
        "call_of_the_eight_too_early", e8,
        [](json& d) {
            d["state"]["call"] = {{"ball", 8}, {"pocket", "N"}};
        },
        "state.call.ball");
    add(
        "call_of_an_unknown_pocket", e8,
        [](json& d) {
            d["state"]["call"] = {{"ball", 3}, {"pocket", "E"}};
        },
        "state.call.pocket");
    add(
        "call_unknown_word", e8, [](json& d) { d["state"]["call"] = "bank"; }, "state.call");
    add(
        "call_in_nine_ball", n9,
        [](json& d) {
            d["state"]["call"] = {{"ball", 1}, {"pocket", "N"}};
        },
        "state.call");
    add(
        "call_on_the_break", brk, [](json& d) { d["state"]["call"] = "safety"; }, "state.call");
    add(
        "push_out_in_eight_ball", e8, [](json& d) { d["state"]["shot"] = "push_out"; },
        "state.shot");
    add(
        "after_push_out_in_eight_ball", e8, [](json& d) { d["state"]["shot"] = "after_push_out"; },
        "state.shot");
    add(
        "push_out_with_ball_in_hand", n9,
        [](json& d) {
            d["state"]["shot"] = "push_out";
            d["state"]["cue_ball"] = "in_hand";
        },
        "state.shot");
    add(
        "position_of_ball_not_on_table", e8,
        [](json& d) {
            d["state"]["on_table"] = {1, 8};
            d["state"]["call"] = nullptr;
            d["state"]["positions"] = {{"3", {1.0, 0.5}}};
        },
        "state.positions.3");
    add(
        "position_key_not_an_id", e8,
        [](json& d) {
            d["state"]["positions"] = {{"x", {1.0, 0.5}}};
        },
        "state.positions.x");
    add(
        "positions_overlap", e8,
        [](json& d) {
            d["state"]["positions"] = {{"1", {1.0, 0.5}}, {"2", {1.01, 0.5}}};
        },
        "state.positions.2");
    add(
        "position_off_the_table", e8,
        [](json& d) {
            d["state"]["positions"] = {{"1", {3.0, 0.5}}};
        },
        "state.positions.1");
    add(
        "kitchen_cue_ball_outside_the_kitchen", brk,
        [](json& d) {
            d["state"]["positions"]["0"] = {1.0, 0.6};
        },
        "state.positions.0");
    add(
        "event_on_ball_not_on_table", e8,
        [](json& d) {
            d["state"]["on_table"] = {3, 8};
            d["events"] = {ev("ball_ball", {0, 3}), pot(5, "N")};
        },
        "events[1].balls[0]");
    add(
        "event_unknown_ball", e8,
        [](json& d) {
            d["events"] = {ev("ball_ball", {0, 16})};
        },
        "events[0].balls[1]");
    add(
        "nine_ball_event_on_ball_twelve", n9, [](json& d) { d["events"] = {ev("cushion", {12})}; },
        "events[0].balls[0]");
    add(
        "event_unknown_type", e8, [](json& d) { d["events"] = {ev("bounce", {0})}; },
        "events[0].type");
    add(
        "event_missing_type", e8,
        [](json& d) {
            d["events"] = {{{"balls", {0}}}};
        },
        "events[0].type");
    add(
        "event_unknown_field", e8,
        [](json& d) {
            json e = ev("cushion", {0});
            e["rail"] = "W";
            d["events"] = {e};
        },
        "events[0].rail");
    add(
        "ball_ball_with_one_ball", e8, [](json& d) { d["events"] = {ev("ball_ball", {0})}; },
        "events[0].balls");
    add(
        "ball_ball_with_itself", e8,
        [](json& d) {
            d["events"] = {ev("ball_ball", {3, 3})};
        },
        "events[0].balls");
    add(
        "pocket_event_without_pocket", e8, [](json& d) { d["events"] = {ev("pocket", {3})}; },
        "events[0].pocket");
    add(
        "pocket_event_unknown_pocket", e8, [](json& d) { d["events"] = {pot(3, "X")}; },
        "events[0].pocket");
    add(
        "pocket_on_a_cushion_event", e8,
        [](json& d) {
            json e = ev("cushion", {3});
            e["pocket"] = "N";
            d["events"] = {e};
        },
        "events[0].pocket");
    add(
        "unknown_cushion", e8,
        [](json& d) {
            json e = ev("cushion", {3});
            e["cushion"] = "NE-E";
            d["events"] = {e};
        },
        "events[0].cushion");
    add(
        "positions_per_ball", e8,
        [](json& d) {
            json e = ev("ball_ball", {0, 3});
            e["pos"] = {{0.5, 0.5}};
            d["events"] = {e};
        },
        "events[0].pos");
    add(
        "struck_object_ball", e8, [](json& d) { d["events"] = {ev("strike", {3})}; },
        "events[0].balls[0]");
    add(
        "events_not_an_array", e8, [](json& d) { d["events"] = json::object(); }, "events");
    return cases;
}

class JudgeBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(JudgeBadInput, NamesThePath) {
    EXPECT_EQ(bad_path(GetParam().doc), GetParam().path);
}

std::string case_name(const ::testing::TestParamInfo<BadCase>& param) {
    return param.param.name;
}

INSTANTIATE_TEST_SUITE_P(Judge, JudgeBadInput, ::testing::ValuesIn(bad_cases()), case_name);

TEST(JudgeBinary, PrintsTheVerdict) {
    cli_test::CliResult r = cli_test::run_cli("judge", contract_example().dump());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(r.err.empty());
    json out = json::parse(r.out);
    EXPECT_EQ(out["break"], "legal");
    EXPECT_EQ(out["state"]["shooter"], "A");
    // Byte-identical on a second run.
    EXPECT_EQ(cli_test::run_cli("judge", contract_example().dump()).out, r.out);
}

TEST(JudgeBinary, BadInputExitsTwoWithOneLine) {
    json doc = eight_ball_groups();
    doc["state"]["on_table"] = {1, 8};
    cli_test::CliResult r = cli_test::run_cli("judge -", doc.dump());
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(r.out.empty());
    EXPECT_EQ(r.err.rfind("error: state.call.ball: ", 0), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1);
}

}  // namespace
