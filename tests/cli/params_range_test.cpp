// The accepted range of each physical parameter (docs/cli.md, `params`): both ends of every
// range run (a break at the fastest cue speed, and a fast ball with spin, finish with exit 0);
// a value outside is bad input naming the field and the range.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/json_in.hpp"
#include "cli_process.hpp"

namespace {

struct Range {
    std::string field;
    double lo, hi;
    bool zero_ok = false;
};

const std::vector<Range> kRanges = {
    {"ball_radius", 0.01, 0.05},    {"ball_mass", 0.01, 10.0},      {"gravity", 0.1, 100.0},
    {"mu_slide", 0.001, 1.0, true}, {"mu_roll", 0.0001, 1.0, true}, {"spin_decel", 0.01, 1000.0},
    {"e_ball", 0.0, 1.0},           {"mu_ball", 0.0, 1.0},          {"e_cushion", 0.0, 1.0},
    {"mu_cushion", 0.0, 1.0},       {"cue_mass", 0.1, 10.0},        {"cue_tip_e", 0.0, 1.0},
    {"cue_endmass", 0.001, 1.0},    {"miscue_limit", 0.01, 1.0},
};

// The shots each value must run: a 9-ball break at the fastest cue speed with spin and
// elevation, and a lone ball at the fastest speed and spin on the unbounded table.
std::vector<nlohmann::json> shots(const std::string& field, double value) {
    nlohmann::json brk = {
        {"rack", {{"game", "9ball"}, {"seed", 3}}},
        {"strike", {{"speed", 20}, {"side", 0.3}, {"top", -0.4}, {"elevation_deg", 10}}},
        {"params", {{field, value}}}};
    nlohmann::json lone = {
        {"table", "unbounded"},
        {"balls", {{{"id", 1}, {"pos", {0, 0}}, {"vel", {99, 0}}, {"spin", {0, 7000, 7000}}}}},
        {"params", {{field, value}}}};
    if (field == "ball_radius") {
        // The cushion's nose must meet a ball of this radius above its centre.
        brk["table"] = {{"preset", "9ft"}, {"cushion_height", 1.6 * value}};
    }
    return {brk, lone};
}

void expect_runs(const std::string& field, double value) {
    for (const nlohmann::json& doc : shots(field, value)) {
        std::string out;
        EXPECT_NO_THROW(out = cli::run_document(cli::DocumentVerb::simulate, doc.dump()))
            << field << " = " << value << ": " << doc.dump();
        EXPECT_FALSE(out.empty());
    }
}

void expect_refused(const std::string& field, double value) {
    const nlohmann::json doc = shots(field, value)[0];
    try {
        (void)cli::run_document(cli::DocumentVerb::simulate, doc.dump());
        ADD_FAILURE() << field << " = " << value << " was accepted";
    } catch (const cli::BadInput& e) {
        EXPECT_EQ(e.path(), "params." + field);
        EXPECT_NE(e.detail().find("out of range: must be"), std::string::npos) << e.what();
    }
}

TEST(ParamsRange, BothEndsOfEveryRangeRun) {
    for (const Range& r : kRanges) {
        expect_runs(r.field, r.lo);
        expect_runs(r.field, r.hi);
        if (r.zero_ok) expect_runs(r.field, 0.0);
    }
}

TEST(ParamsRange, ValuesOutsideAreRefusedNamingTheField) {
    for (const Range& r : kRanges) {
        expect_refused(r.field, r.hi * 1.01);
        expect_refused(r.field, r.lo > 0 ? r.lo * 0.99 : -1e-9);
        if (r.lo > 0 && !r.zero_ok) expect_refused(r.field, 0.0);
    }
}

TEST(ParamsRange, AllEndsAtOnceRun) {
    // The slowest friction and gravity together: the longest shots the ranges allow.
    nlohmann::json doc = shots("mu_slide", 0.001)[1];
    doc["params"] = {{"mu_slide", 0.001},
                     {"mu_roll", 0.0001},
                     {"gravity", 0.1},
                     {"spin_decel", 0.01},
                     {"ball_mass", 0.01}};
    EXPECT_NO_THROW((void)cli::run_document(cli::DocumentVerb::simulate, doc.dump()));
    doc["table"] = "9ft";
    doc["balls"][0]["pos"] = {1.0, 0.6};
    EXPECT_NO_THROW((void)cli::run_document(cli::DocumentVerb::simulate, doc.dump()));
}

TEST(ParamsRange, TinyLegalLookingValuesExitTwoNotOne) {
    // Tiny values that look legal are bad input (exit 2), never a non-finite number from the
    // engine (an internal error, exit 1).
    for (const char* param : {"\"ball_mass\": 5e-324", "\"mu_slide\": 1e-300",
                              "\"gravity\": 1e-300", "\"mu_roll\": 1e-300"}) {
        const std::string doc = std::string(R"({"balls":[{"id":0,"pos":[1,0.6]}],)") +
                                R"("strike":{"speed":1},"params":{)" + param + "}}";
        const cli_test::CliResult r = cli_test::run_cli("simulate", doc);
        EXPECT_EQ(r.status, 2) << param << ": " << r.err;
        EXPECT_EQ(r.err.rfind("error: params.", 0), 0u) << r.err;
        EXPECT_NE(r.err.find("out of range"), std::string::npos) << r.err;
    }
}

}  // namespace
