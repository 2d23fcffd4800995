// `simulate` on valid documents: the output's shape, samples, truncation, determinism, and
// number formatting (docs/cli.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/json_in.hpp"
#include "cli_process.hpp"

namespace {

using cli_test::run_cli;
using nlohmann::json;
using nlohmann::ordered_json;

constexpr double R = 0.028575;
constexpr double L = 2.540;
constexpr double W = 1.270;

ordered_json simulate(const std::string& text) {
    return cli::simulate_command(cli::parse_document(text));
}

const std::string kBreak = R"({"rack": {"game": "8ball", "seed": 7},
                               "strike": {"speed": 6.7, "heading_deg": 0}})";

TEST(Simulate, MinimalDocumentHasTheContractKeysInOrder) {
    ordered_json out = simulate(R"({"balls": [{"id": 0, "pos": [0.635, 0.635]}]})");
    std::vector<std::string> keys;
    for (auto it = out.begin(); it != out.end(); ++it) keys.push_back(it.key());
    EXPECT_EQ(keys, (std::vector<std::string>{"events", "final", "samples", "rest_time",
                                              "event_count", "truncated"}));
    EXPECT_TRUE(out["events"].empty());
    EXPECT_EQ(out["event_count"], 0);
    EXPECT_EQ(out["truncated"], false);
    ASSERT_EQ(out["final"].size(), 1u);
    EXPECT_EQ(out["final"][0]["id"], 0);
    EXPECT_EQ(out["final"][0]["pos"], ordered_json::array({0.635, 0.635}));
    EXPECT_EQ(out["final"][0]["state"], "stationary");
    EXPECT_FALSE(out["final"][0].contains("pocket"));
    EXPECT_TRUE(out["samples"].empty());
    EXPECT_TRUE(out["rest_time"].is_number());
}

TEST(Simulate, StrikeIsTheFirstEventAndEventsAreInTimeOrder) {
    ordered_json out = simulate(R"({"table": "9ft",
        "balls": [{"id": 0, "pos": [0.635, 0.635]}, {"id": 1, "pos": [1.905, 0.635]}],
        "strike": {"speed": 3.0, "heading_deg": 0, "side": 0, "top": 0, "elevation_deg": 0}})");
    const ordered_json& events = out["events"];
    ASSERT_FALSE(events.empty());
    EXPECT_EQ(out["event_count"], events.size());
    EXPECT_EQ(events[0]["type"], "strike");
    EXPECT_EQ(events[0]["time"], 0.0);
    EXPECT_EQ(events[0]["balls"], ordered_json::array({0}));
    EXPECT_GT(events[0]["vel"][0][0].get<double>(), 0.0);
    bool hit = false;
    double t = 0.0;
    for (const ordered_json& e : events) {
        EXPECT_GE(e["time"].get<double>(), t) << e.dump();
        t = e["time"].get<double>();
        const std::size_t n = e["balls"].size();
        ASSERT_TRUE(n == 1 || n == 2) << e.dump();
        EXPECT_EQ(e["pos"].size(), n);
        EXPECT_EQ(e["vel"].size(), n);
        EXPECT_EQ(e["spin"].size(), n);
        for (std::size_t k = 0; k < n; ++k) {
            EXPECT_EQ(e["pos"][k].size(), 2u);
            EXPECT_EQ(e["vel"][k].size(), 2u);
            EXPECT_EQ(e["spin"][k].size(), 3u);
        }
        const std::string type = e["type"];
        if (type == "transition") {
            EXPECT_TRUE(e.contains("from") && e.contains("to")) << e.dump();
        } else if (type == "ball_ball") {
            hit = true;
            EXPECT_EQ(e["balls"], ordered_json::array({0, 1}));
            EXPECT_GT(e["speed"].get<double>(), 0.0);
        } else if (type == "cushion") {
            EXPECT_TRUE(e.contains("speed"));
            EXPECT_TRUE(e.contains("cushion") != e.contains("pocket_jaw")) << e.dump();
        } else if (type == "pocket") {
            EXPECT_TRUE(e.contains("pocket"));
        }
    }
    EXPECT_TRUE(hit);
    EXPECT_GE(out["rest_time"].get<double>(), t);
}

TEST(Simulate, RackedBreakEndsWithEveryBallAccountedFor) {
    ordered_json out = simulate(kBreak);
    ASSERT_EQ(out["final"].size(), 16u);
    for (int id = 0; id < 16; ++id) {
        const ordered_json& b = out["final"][static_cast<std::size_t>(id)];
        EXPECT_EQ(b["id"], id);
        if (b["state"] == "pocketed") {
            EXPECT_TRUE(b["pos"].is_null());
            EXPECT_TRUE(b["pocket"].is_string());
        } else {
            EXPECT_EQ(b["state"], "stationary") << b.dump();
            const double x = b["pos"][0], y = b["pos"][1];
            EXPECT_GT(x, -0.1);
            EXPECT_LT(x, L + 0.1);
            EXPECT_GT(y, -0.1);
            EXPECT_LT(y, W + 0.1);
        }
    }
    EXPECT_EQ(out["truncated"], false);
    EXPECT_EQ(out["events"][0]["type"], "strike");
}

TEST(Simulate, SamplesAreReportedInTheOrderGiven) {
    ordered_json out = simulate(R"({"balls": [{"id": 0, "pos": [0.635, 0.635]}],
        "strike": {"speed": 2.0}, "sample_times": [1.0, 0.5, 0.0, 0.5]})");
    const ordered_json& s = out["samples"];
    ASSERT_EQ(s.size(), 4u);
    EXPECT_EQ(s[0]["time"], 1.0);
    EXPECT_EQ(s[1]["time"], 0.5);
    EXPECT_EQ(s[2]["time"], 0.0);
    EXPECT_EQ(s[3], s[1]);
    // At an event's time a sample shows the state after it: the struck ball moves at t = 0.
    ASSERT_EQ(s[2]["balls"].size(), 1u);
    EXPECT_EQ(s[2]["balls"][0]["id"], 0);
    EXPECT_EQ(s[2]["balls"][0]["vel"], out["events"][0]["vel"][0]);
    EXPECT_NE(s[2]["balls"][0]["state"], "stationary");
    // Moving forward along +x.
    EXPECT_GT(s[1]["balls"][0]["pos"][0].get<double>(), 0.635);
    EXPECT_GT(s[0]["balls"][0]["pos"][0].get<double>(), s[1]["balls"][0]["pos"][0].get<double>());
}

TEST(Simulate, SamplesNeverChangeTheSimulation) {
    ordered_json plain = simulate(kBreak);
    json with = json::parse(kBreak);
    with["sample_times"] = {0.1, 2.0, 0.05};
    ordered_json sampled = cli::simulate_command(with);
    EXPECT_EQ(plain["events"], sampled["events"]);
    EXPECT_EQ(plain["final"], sampled["final"]);
}

TEST(Simulate, PocketedBallSampleHasNullPosition) {
    // Ball 1 rolls straight into the SW corner pocket.
    ordered_json out = simulate(R"({"balls": [{"id": 1, "pos": [0.3, 0.3], "vel": [-1.0, -1.0],
        "spin": [-35.0, 35.0, 0]}], "sample_times": [0, 30]})");
    ASSERT_EQ(out["final"].size(), 1u);
    EXPECT_EQ(out["final"][0]["state"], "pocketed") << out.dump();
    EXPECT_EQ(out["final"][0]["pocket"], "SW");
    EXPECT_TRUE(out["final"][0]["pos"].is_null());
    const ordered_json& late = out["samples"][1]["balls"][0];
    EXPECT_TRUE(late["pos"].is_null());
    EXPECT_EQ(late["state"], "pocketed");
    EXPECT_EQ(late["pocket"], "SW");
    const ordered_json& early = out["samples"][0]["balls"][0];
    EXPECT_EQ(early["pos"], ordered_json::array({0.3, 0.3}));
    bool pocket_event = false;
    for (const ordered_json& e : out["events"])
        if (e["type"] == "pocket") {
            pocket_event = true;
            EXPECT_EQ(e["pocket"], "SW");
            EXPECT_TRUE(e["pos"][0].is_array());  // a pocketed ball shows its last position
        }
    EXPECT_TRUE(pocket_event);
}

TEST(Simulate, EventCapTruncatesAndSaysSo) {
    json doc = json::parse(kBreak);
    doc["max_events"] = 5;
    doc["sample_times"] = {100.0};
    ordered_json out = cli::simulate_command(doc);
    EXPECT_EQ(out["truncated"], true);
    EXPECT_TRUE(out["rest_time"].is_null());
    EXPECT_EQ(out["event_count"], 5);
    EXPECT_EQ(out["events"].size(), 5u);
    EXPECT_EQ(out["final"].size(), 16u);
    EXPECT_EQ(out["samples"][0]["balls"].size(), 16u);
}

TEST(Simulate, TableOverridesAndModelsAreAccepted) {
    ordered_json out = simulate(R"({
        "table": {"preset": "7ft", "pockets": false, "cushion_height": 0.0363,
                  "corner_shelf": 0.02, "side_shelf": 0.004, "jaw_depth": 0.06},
        "params": {"mu_ball": 0.06, "e_cushion": 0.8, "mu_slide": 0.25},
        "models": {"ball_ball": "frictionless", "cushion": "simple"},
        "balls": [{"id": 0, "pos": [0.5, 0.5]}], "strike": {"speed": 4, "heading_deg": 30}})");
    for (const ordered_json& e : out["events"]) EXPECT_NE(e["type"], "pocket");
    EXPECT_EQ(out["final"][0]["state"], "stationary");
}

TEST(Simulate, UnboundedTableHasNoCushions) {
    ordered_json out = simulate(R"({"table": "unbounded",
        "balls": [{"id": 0, "pos": [0.5, 0.5]}], "strike": {"speed": 8}})");
    for (const ordered_json& e : out["events"]) {
        EXPECT_NE(e["type"], "cushion");
        EXPECT_NE(e["type"], "pocket");
    }
    EXPECT_GT(out["final"][0]["pos"][0].get<double>(), L);
}

TEST(Simulate, ParamsChangeTheResult) {
    const std::string a = R"({"balls": [{"id": 0, "pos": [0.5, 0.6]}], "strike": {"speed": 2}})";
    const std::string b = R"({"params": {"mu_roll": 0.02},
        "balls": [{"id": 0, "pos": [0.5, 0.6]}], "strike": {"speed": 2}})";
    EXPECT_GT(simulate(a)["rest_time"].get<double>(), simulate(b)["rest_time"].get<double>());
}

TEST(Simulate, TouchingBallsAreValid) {
    // 2R apart exactly: frozen, not overlapping.
    const double x2 = 1.0 + 2 * R;
    json doc = {{"balls", {{{"id", 1}, {"pos", {1.0, 0.6}}}, {{"id", 2}, {"pos", {x2, 0.6}}}}}};
    EXPECT_NO_THROW(cli::simulate_command(doc));
}

TEST(SimulateProcess, OutputIsByteIdenticalRunToRun) {
    auto a = run_cli("simulate", kBreak);
    auto b = run_cli("simulate -", kBreak);
    ASSERT_EQ(a.status, 0) << a.err;
    EXPECT_EQ(a.err, "");
    EXPECT_EQ(a.out, b.out);
    EXPECT_EQ(a.out.back(), '\n');
    EXPECT_EQ(a.out.find('\n'), a.out.size() - 1) << "compact output is one line";
}

TEST(SimulateProcess, ReadsAFile) {
    const auto path = cli_test::temp_path("doc");
    {
        std::ofstream f(path);
        f << kBreak;
    }
    auto a = run_cli("simulate '" + path.string() + "'");
    std::filesystem::remove(path);
    ASSERT_EQ(a.status, 0) << a.err;
    EXPECT_EQ(a.out, run_cli("simulate", kBreak).out);
}

TEST(SimulateProcess, PrettyParsesToTheSameDocument) {
    auto compact = run_cli("simulate", kBreak);
    auto pretty = run_cli("simulate --pretty", kBreak);
    ASSERT_EQ(pretty.status, 0) << pretty.err;
    EXPECT_NE(compact.out, pretty.out);
    EXPECT_GT(std::count(pretty.out.begin(), pretty.out.end(), '\n'), 10);
    EXPECT_EQ(json::parse(compact.out), json::parse(pretty.out));
}

TEST(SimulateProcess, NumbersReadBackExactlyAndNoNegativeZero) {
    auto r = run_cli("simulate", kBreak);
    ASSERT_EQ(r.status, 0) << r.err;
    // Output values are the engine's doubles, bit for bit.
    ordered_json direct = simulate(kBreak);
    ordered_json parsed = ordered_json::parse(r.out);
    ASSERT_EQ(parsed["events"].size(), direct["events"].size());
    for (std::size_t i = 0; i < direct["events"].size(); ++i) {
        const double t0 = direct["events"][i]["time"], t1 = parsed["events"][i]["time"];
        EXPECT_EQ(t0, t1);
        const double x0 = direct["events"][i]["pos"][0][0], x1 = parsed["events"][i]["pos"][0][0];
        EXPECT_EQ(x0, x1);
    }
    EXPECT_FALSE(std::regex_search(r.out, std::regex(R"(-0(\.0+)?([,\]}]|e))")))
        << "negative zero in the output";
    EXPECT_EQ(r.out.find("null,\"state\":\"stationary\""), std::string::npos);
}

}  // namespace

namespace {

TEST(BreakSummary, SummarizesASeededBreak) {
    if (std::system("python3 --version > /dev/null 2>&1") != 0) GTEST_SKIP() << "no python3";
    // COOLAABER_TEST_DATA is <root>/tests/cli/data (it need not exist).
    const std::string script =
        (std::filesystem::path(COOLAABER_TEST_DATA).parent_path().parent_path().parent_path() /
         "scripts" / "break_summary.py")
            .string();
    auto sim = run_cli("simulate", kBreak);
    ASSERT_EQ(sim.status, 0) << sim.err;
    const auto in = cli_test::temp_path("sim-out"), out = cli_test::temp_path("summary");
    {
        std::ofstream f(in);
        f << sim.out;
    }
    const std::string command =
        "python3 '" + script + "' < '" + in.string() + "' > '" + out.string() + "' 2>&1";
    const int status = std::system(command.c_str());
    const std::string summary = cli_test::slurp(out);
    std::filesystem::remove(in);
    std::filesystem::remove(out);
    EXPECT_EQ(status, 0) << summary;
    EXPECT_NE(summary.find("Pocketed"), std::string::npos) << summary;
    EXPECT_NE(summary.find("Events: "), std::string::npos) << summary;
    EXPECT_NE(summary.find("Time to rest: "), std::string::npos) << summary;
    EXPECT_NE(summary.find("Truncated: no"), std::string::npos) << summary;
}

}  // namespace
