// `bench`: one entry per standard scene with timings, events and runs.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/json_in.hpp"
#include "cli_process.hpp"
#include "physics/scenes.hpp"

namespace {

TEST(Bench, ReportsEveryStandardScene) {
    nlohmann::ordered_json out = cli::bench_command(5);
    auto names = physics::standard_scene_names();
    names.push_back("snooker_break");
    names.push_back("three_cushion");
    ASSERT_EQ(out["scenes"].size(), names.size());
    for (const std::string& name : names) {
        const auto& s = out["scenes"][name];
        EXPECT_EQ(s["runs"], 5) << name;
        EXPECT_GT(s["events"].get<int>(), 0) << name;
        EXPECT_GT(s["median_us"].get<double>(), 0.0) << name;
        EXPECT_LE(s["median_us"].get<double>(), s["p95_us"].get<double>()) << name;
    }
    EXPECT_NE(out["machine"].get<std::string>().find("core"), std::string::npos);
#ifdef NDEBUG
    EXPECT_EQ(out["build"], "release");
#else
    EXPECT_EQ(out["build"], "debug");
#endif
}

TEST(Bench, RunsOutOfRangeIsBadInput) {
    EXPECT_THROW(cli::bench_command(0), cli::BadInput);
    EXPECT_THROW(cli::bench_command(-5), cli::BadInput);
}

TEST(BenchProcess, PrintsOneJsonObject) {
    auto r = cli_test::run_cli("bench --runs 3");
    ASSERT_EQ(r.status, 0) << r.err;
    auto out = nlohmann::json::parse(r.out);
    EXPECT_TRUE(out["scenes"].contains("break"));
    EXPECT_TRUE(out["scenes"].contains("cut"));
    EXPECT_TRUE(out["scenes"].contains("long_roll"));
}

}  // namespace
