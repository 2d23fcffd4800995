// Bad input to `simulate` and bad command lines: exit status 2, nothing on stdout, and exactly
// one line on stderr, "error: <json path>: <message>" (docs/cli.md).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_process.hpp"

namespace {

using cli_test::CliResult;
using cli_test::run_cli;

struct BadCase {
    std::string name;
    std::string input;
    std::string path;     ///< the JSON path the error must name
    std::string message;  ///< a piece of the message (may be empty)
};

std::ostream& operator<<(std::ostream& os, const BadCase& c) {
    return os << c.name;
}

// Two valid balls to build documents around.
const std::string kCue = R"({"id": 0, "pos": [0.635, 0.635]})";
const std::string kOne = R"({"id": 1, "pos": [1.905, 0.635]})";
const std::string kBalls = R"("balls": [)" + kCue + ", " + kOne + "]";

std::string doc(const std::string& fields) {
    return "{" + kBalls + ", " + fields + "}";
}

std::string many_times(int n) {
    std::string s = "[";
    for (int i = 0; i < n; ++i) s += (i ? ",0.5" : "0.5");
    return s + "]";
}

void expect_bad_input(const CliResult& r, const std::string& path, const std::string& message) {
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.out, "") << "nothing on stdout on bad input";
    const std::string prefix = "error: " + path + ": ";
    EXPECT_EQ(r.err.substr(0, prefix.size()), prefix) << r.err;
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "exactly one line: " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
}

class SimulateBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(SimulateBadInput, ExitsTwoNamingThePath) {
    const BadCase& c = GetParam();
    expect_bad_input(run_cli("simulate", c.input), c.path, c.message);
}

const std::vector<BadCase> kCases = {
    // Unparsable or unusable documents.
    {"unparsable", R"({"balls": [)", "input", "not valid JSON"},
    {"empty", "", "input", "not valid JSON"},
    {"trailing_garbage", "{} x", "input", "not valid JSON"},
    {"huge_number", R"({"max_events": 1e400})", "input", ""},
    {"not_an_object", "[1, 2]", "input", "expected an object"},
    {"duplicate_field", doc(R"("params": {"mu_slide": 0.2, "mu_slide": 0.3})"), "params.mu_slide",
     "twice"},
    // Unknown fields at several depths.
    {"unknown_top", doc(R"("balls_typo": 1)"), "balls_typo", "unknown field"},
    {"unknown_params", doc(R"("params": {"mu_slid": 0.2})"), "params.mu_slid", "unknown field"},
    {"unknown_models", doc(R"("models": {"ball": "frictional"})"), "models.ball", "unknown field"},
    {"unknown_ball",
     R"({"balls": [)" + kCue + R"(, {"id": 1, "pos": [1, 0.6], "velocity": [0, 0]}]})",
     "balls[1].velocity", "unknown field"},
    {"unknown_strike", doc(R"("strike": {"speed": 1, "spd": 2})"), "strike.spd", "unknown field"},
    {"unknown_table", doc(R"("table": {"preset": "9ft", "lenght": 2.5})"), "table.lenght",
     "unknown field"},
    {"unknown_rack", R"({"rack": {"game": "8ball", "sed": 1}})", "rack.sed", "unknown field"},
    // Wrong types.
    {"balls_not_array", R"({"balls": {"id": 0}})", "balls", "expected an array"},
    {"ball_not_object", R"({"balls": [3]})", "balls[0]", "expected an object"},
    {"pos_string", R"({"balls": [{"id": 0, "pos": "here"}]})", "balls[0].pos", "[x, y]"},
    {"pos_three_numbers", R"({"balls": [{"id": 0, "pos": [0.5, 0.5, 0]}]})", "balls[0].pos",
     "[x, y]"},
    {"pos_element_string", R"({"balls": [{"id": 0, "pos": [0.5, "0.5"]}]})", "balls[0].pos[1]",
     "expected a number"},
    {"spin_two_numbers", R"({"balls": [{"id": 0, "pos": [0.5, 0.5], "spin": [0, 0]}]})",
     "balls[0].spin", "[x, y, z]"},
    {"id_string", R"({"balls": [{"id": "cue", "pos": [0.5, 0.5]}]})", "balls[0].id",
     "expected an integer"},
    {"id_fraction", R"({"balls": [{"id": 1.5, "pos": [0.5, 0.5]}]})", "balls[0].id",
     "expected an integer"},
    {"param_string", doc(R"("params": {"mu_slide": "0.2"})"), "params.mu_slide",
     "expected a number"},
    {"mu_ball_string", doc(R"("params": {"mu_ball": "fit"})"), "params.mu_ball",
     "expected a number"},
    {"strike_speed_string", doc(R"("strike": {"speed": "fast"})"), "strike.speed",
     "expected a number"},
    {"strike_not_object", doc(R"("strike": 3)"), "strike", "expected an object"},
    {"pockets_number", doc(R"("table": {"pockets": 1})"), "table.pockets", "true or false"},
    {"table_number", doc(R"("table": 9)"), "table", "preset name"},
    {"max_events_fraction", doc(R"("max_events": 1.5)"), "max_events", "expected an integer"},
    {"sample_times_number", doc(R"("sample_times": 0.5)"), "sample_times", "expected an array"},
    {"model_number", doc(R"("models": {"cushion": 1})"), "models.cushion", "expected a string"},
    // Values out of range.
    {"restitution_above_1", doc(R"("params": {"e_ball": 1.5})"), "params.e_ball", "out of range"},
    {"restitution_below_0", doc(R"("params": {"e_cushion": -0.1})"), "params.e_cushion",
     "out of range"},
    {"negative_friction", doc(R"("params": {"mu_slide": -0.1})"), "params.mu_slide",
     "out of range"},
    {"negative_mu_ball", doc(R"("params": {"mu_ball": -0.1})"), "params.mu_ball", "out of range"},
    {"zero_radius", doc(R"("params": {"ball_radius": 0})"), "params.ball_radius", "out of range"},
    {"zero_mass", doc(R"("params": {"ball_mass": 0})"), "params.ball_mass", "out of range"},
    {"negative_gravity", doc(R"("params": {"gravity": -9.81})"), "params.gravity", "out of range"},
    {"zero_miscue_limit", doc(R"("params": {"miscue_limit": 0})"), "params.miscue_limit",
     "out of range"},
    {"unknown_model", doc(R"("models": {"cushion": "han2010"})"), "models.cushion",
     "unknown value"},
    {"strike_too_fast", doc(R"("strike": {"speed": 25})"), "strike.speed", "out of range"},
    {"strike_negative", doc(R"("strike": {"speed": -1})"), "strike.speed", "out of range"},
    {"strike_no_speed", doc(R"("strike": {"heading_deg": 10})"), "strike.speed", "missing"},
    {"elevation_above_90", doc(R"("strike": {"speed": 1, "elevation_deg": 91})"),
     "strike.elevation_deg", "out of range"},
    {"side_beyond_ball", doc(R"("strike": {"speed": 1, "side": 1.5})"), "strike.side",
     "out of range"},
    {"max_events_zero", doc(R"("max_events": 0)"), "max_events", "out of range"},
    {"max_events_huge", doc(R"("max_events": 20000000)"), "max_events", "out of range"},
    {"max_events_over_the_cap", doc(R"("max_events": 1000001)"), "max_events", "out of range"},
    {"sample_time_negative", doc(R"("sample_times": [0.5, -1])"), "sample_times[1]",
     "out of range"},
    {"sample_time_huge", doc(R"("sample_times": [1e308])"), "sample_times[0]", "out of range"},
    {"too_many_sample_times", doc(R"("sample_times": )" + many_times(10001)), "sample_times",
     "at most 10000"},
    {"ball_too_fast", R"({"balls": [{"id": 1, "pos": [1, 0.6], "vel": [300, 0]}]})", "balls[0].vel",
     "too fast"},
    // Balls.
    {"unknown_ball_id", R"({"balls": [{"id": 22, "pos": [1, 0.6]}]})", "balls[0].id",
     "out of range"},
    {"negative_ball_id", R"({"balls": [{"id": -1, "pos": [1, 0.6]}]})", "balls[0].id",
     "out of range"},
    {"duplicate_id", R"({"balls": [{"id": 3, "pos": [1, 0.6]}, {"id": 3, "pos": [1.5, 0.6]}]})",
     "balls[1].id", "twice"},
    {"missing_pos", R"({"balls": [{"id": 3}]})", "balls[0].pos", "missing"},
    {"missing_id", R"({"balls": [{"pos": [1, 0.6]}]})", "balls[0].id", "missing"},
    {"overlapping_balls",
     R"({"balls": [{"id": 1, "pos": [1, 0.6]}, {"id": 5, "pos": [1.05, 0.6]}]})", "balls[1].pos",
     "overlaps"},
    {"ball_off_table_x", R"({"balls": [{"id": 0, "pos": [-0.1, 0.6]}]})", "balls[0].pos", ""},
    {"ball_in_cushion",
     R"({"balls": [{"id": 1, "pos": [1.0, 0.6]}, {"id": 2, "pos": [1.0, 1.26]}]})", "balls[1].pos",
     ""},
    {"too_many_balls",
     R"({"balls": [{"id":0,"pos":[0.1,0.1]},{"id":1,"pos":[0.2,0.1]},{"id":2,"pos":[0.3,0.1]},
        {"id":3,"pos":[0.4,0.1]},{"id":4,"pos":[0.5,0.1]},{"id":5,"pos":[0.6,0.1]},
        {"id":6,"pos":[0.7,0.1]},{"id":7,"pos":[0.8,0.1]},{"id":8,"pos":[0.9,0.1]},
        {"id":9,"pos":[1.0,0.1]},{"id":10,"pos":[1.1,0.1]},{"id":11,"pos":[1.2,0.1]},
        {"id":12,"pos":[1.3,0.1]},{"id":13,"pos":[1.4,0.1]},{"id":14,"pos":[1.5,0.1]},
        {"id":15,"pos":[1.6,0.1]},{"id":16,"pos":[1.7,0.1]},{"id":17,"pos":[1.8,0.1]},
        {"id":18,"pos":[1.9,0.1]},{"id":19,"pos":[2.0,0.1]},{"id":20,"pos":[2.1,0.1]},
        {"id":21,"pos":[2.2,0.1]},{"id":21,"pos":[2.3,0.1]}]})",
     "balls", "at most 22"},
    {"no_balls", R"({"strike": {"speed": 1}})", "balls", "missing"},
    {"balls_and_rack", R"({"balls": [], "rack": {"game": "8ball"}})", "rack", "not both"},
    // Strike on a missing or moving cue ball.
    {"strike_without_cue_ball", R"({"balls": [)" + kOne + R"(], "strike": {"speed": 1}})", "strike",
     "no ball 0"},
    {"strike_moving_cue_ball",
     R"({"balls": [{"id": 0, "pos": [0.6, 0.6], "vel": [0.5, 0]}], "strike": {"speed": 1}})",
     "balls[0].vel", "at rest"},
    {"strike_spinning_cue_ball",
     R"({"balls": [)" + kOne + R"(, {"id": 0, "pos": [0.6, 0.6], "spin": [0, 0, 3]}],
        "strike": {"speed": 1}})",
     "balls[1].spin", "at rest"},
    // Racks.
    {"rack_unknown_game", R"({"rack": {"game": "bowls"}})", "rack.game", "unknown value"},
    {"rack_negative_seed", R"({"rack": {"game": "9ball", "seed": -3}})", "rack.seed",
     "out of range"},
    {"rack_cue_on_the_apex", R"({"rack": {"game": "8ball", "cue_pos": [1.905, 0.635]}})",
     "rack.cue_pos", ""},
    {"rack_cue_off_table", R"({"rack": {"game": "8ball", "cue_pos": [3.0, 0.635]}})",
     "rack.cue_pos", ""},
    // Tables.
    {"unknown_preset", doc(R"("table": "10ft")"), "table", "unknown value"},
    {"unknown_preset_in_object", doc(R"("table": {"preset": "10ft"})"), "table.preset",
     "unknown value"},
    {"negative_length", doc(R"("table": {"length": -2})"), "table.length", "out of range"},
    {"facing_angle", doc(R"("table": {"corner_facing_deg": 200})"), "table.corner_facing_deg",
     "out of range"},
    {"mouth_smaller_than_ball", doc(R"("table": {"corner_mouth": 0.03})"), "table.corner_mouth",
     ""},
    // Found by fuzz_simulate: the engine made NaNs of a 1 m cushion on a pocketless table.
    {"cushion_height_without_pockets",
     doc(R"("table": {"pockets": false, "cushion_height": 1.0363})"), "table.cushion_height",
     "from R to 2R"},
};

INSTANTIATE_TEST_SUITE_P(Cases, SimulateBadInput, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<BadCase>& param_info) {
                             return param_info.param.name;
                         });

TEST(CommandLine, UnreadableFileIsBadInputNamingTheFile) {
    expect_bad_input(run_cli("simulate /nonexistent/doc.json"), "/nonexistent/doc.json",
                     "cannot open");
}

TEST(CommandLine, DirectoryIsBadInput) {
    CliResult r = run_cli("simulate /");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err.rfind("error: /: ", 0), 0u) << r.err;
}

TEST(CommandLine, MissingVerbIsBadInput) {
    CliResult r = run_cli("");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

TEST(CommandLine, UnknownVerbAndOptionAreBadInput) {
    for (const char* args : {"simulat", "simulate --prety", "bench --runs x", "simulate a b"}) {
        CliResult r = run_cli(args, "{}");
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_EQ(r.out, "") << args;
        EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
        EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
    }
}

TEST(CommandLine, BenchRunsOutOfRange) {
    expect_bad_input(run_cli("bench --runs 0"), "--runs", "out of range");
}

TEST(CommandLine, HelpExitsZero) {
    CliResult r = run_cli("--help");
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.out.find("simulate"), std::string::npos);
}

}  // namespace
