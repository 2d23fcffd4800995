// Practice mode's state (game/practice.hpp, docs/game.md "Practice"): moving balls to legal
// places only, shots with pocketed balls leaving, try again, and a position saved as the
// `simulate` input that coolaaber-cli reads and that loads back to the same numbers.
#include "game/practice.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "../cli/cli_process.hpp"
#include "game/json_field.hpp"
#include "physics/simulate.hpp"

namespace game::test {
namespace {

Practice eight_ball() {
    return Practice(rules::Game::eight_ball, physics::TableSpec{}, physics::Params{}, 3);
}

physics::Stroke break_stroke() {
    physics::Stroke s;
    s.speed = 8.0;
    s.heading_deg = 0.4;
    return s;
}

std::string error_of(const std::string& text) {
    try {
        Practice::from_json(text);
    } catch (const LoadError& e) {
        return e.what();
    }
    return "(read without error)";
}

TEST(Practice, StartsFromTheRackWithTheCueBallOnTheHeadSpot) {
    const Practice p = eight_ball();
    EXPECT_EQ(p.balls().size(), 16u);
    EXPECT_EQ(p.balls().at(0), p.table().head_spot());
    const Practice nine(rules::Game::nine_ball, physics::TableSpec{}, physics::Params{}, 3);
    EXPECT_EQ(nine.balls().size(), 10u);
    EXPECT_FALSE(p.can_try_again());
}

TEST(Practice, AnyBallGoesAnywhereItCanLieAndNowhereElse) {
    Practice p = eight_ball();
    const double R = p.params().ball_radius;
    EXPECT_TRUE(p.move(5, {0.4, 0.3}));
    EXPECT_EQ(p.balls().at(5), (physics::Vec2{0.4, 0.3}));
    EXPECT_TRUE(p.move(0, {0.4 + 2 * R, 0.3})) << "touching is allowed";
    EXPECT_EQ(p.check_move(5, {0.4 + R, 0.3}), "The 5 can't go on top of the cue ball.");
    EXPECT_EQ(p.check_move(0, p.balls().at(1)), "The cue ball can't go on top of the 1.");
    EXPECT_EQ(p.check_move(9, {R / 2, 0.5}), "The 9 must go on the cloth.");
    EXPECT_EQ(p.check_move(9, {std::nan(""), 0.5}), "The 9 must go on the cloth.");
    EXPECT_FALSE(p.move(9, {-1.0, 0.5}));
    EXPECT_NE(p.balls().at(9).x, -1.0) << "a refused move moves nothing";
    p.play(break_stroke());
    for (int id = 1; id <= 15; ++id)
        if (!p.balls().count(id)) {
            EXPECT_EQ(p.check_move(id, {1.0, 0.6}),
                      "The " + std::to_string(id) + " is not on the table.");
            break;
        }
}

TEST(Practice, PocketedBallsLeaveAndTryAgainPutsBackEachPositionExactly) {
    Practice p = eight_ball();
    const auto rack = p.balls();
    const physics::Stroke stroke = break_stroke();
    const physics::Shot expected =
        physics::simulate(p.table(), p.params(), p.ball_states(), &stroke);
    const physics::Shot& shot = p.play(break_stroke());
    EXPECT_EQ(shot.events().size(), expected.events().size());
    int down = 0;
    for (const physics::BallState& b : expected.final_states()) {
        if (b.motion == physics::Motion::pocketed) {
            ++down;
            if (b.id != 0) {
                EXPECT_FALSE(p.balls().count(b.id)) << b.id;
            }
        } else {
            EXPECT_EQ(p.balls().at(b.id), b.pos) << b.id;
        }
    }
    EXPECT_GT(down, 0) << "this break pockets a ball";
    EXPECT_TRUE(p.balls().count(0));
    const auto after_break = p.balls();
    physics::Stroke soft;
    soft.speed = 1.0;
    soft.heading_deg = 90.0;
    p.play(soft);
    p.try_again();
    EXPECT_EQ(p.balls(), after_break);
    p.try_again();
    EXPECT_EQ(p.balls(), rack);
    EXPECT_FALSE(p.can_try_again());
}

TEST(Practice, APocketedCueBallComesBackToTheHeadSpot) {
    Practice p = eight_ball();
    ASSERT_TRUE(p.move(0, {0.15, 0.15}));
    physics::Stroke s;
    s.speed = 1.5;
    s.heading_deg = 225.0;  // straight into the SW corner pocket
    p.play(s);
    EXPECT_EQ(p.balls().at(0), p.table().head_spot());
}

TEST(Practice, SavesAsTheSimulateInputAndLoadsBackTheSameNumbers) {
    Practice p = eight_ball();
    p.play(break_stroke());  // positions with every digit used
    const std::string saved = p.to_json();
    const Practice back = Practice::from_json(saved);
    EXPECT_EQ(back.balls(), p.balls());
    EXPECT_EQ(back.to_json(), saved);

    // coolaaber-cli simulate reads the same file and plays the same shot to the same end.
    nlohmann::json doc = nlohmann::json::parse(saved);
    doc["strike"] = {
        {"speed", 3.0}, {"heading_deg", 10.0}, {"side", 0.0}, {"top", 0.2}, {"elevation_deg", 0.0}};
    const cli_test::CliResult r = cli_test::run_cli("simulate", doc.dump());
    ASSERT_EQ(r.status, 0) << r.err;
    Practice played = Practice::from_json(doc.dump());  // a strike in the file is allowed
    physics::Stroke s;
    s.speed = 3.0;
    s.heading_deg = 10.0;
    s.top = 0.2;
    played.play(s);
    int compared = 0;
    const nlohmann::json out = nlohmann::json::parse(r.out);
    for (const nlohmann::json& b : out.at("final")) {
        const int id = b.at("id").get<int>();
        if (b.at("pos").is_null() || id == 0) continue;
        ++compared;
        EXPECT_EQ(played.balls().at(id).x, b.at("pos")[0].get<double>()) << id;
        EXPECT_EQ(played.balls().at(id).y, b.at("pos")[1].get<double>()) << id;
    }
    EXPECT_GE(compared, 10) << "the object balls left after the break";
}

TEST(Practice, AFileForSimulateWithAPresetLoads) {
    const Practice p = Practice::from_json(
        R"({"table": "7ft", "balls": [{"id": 0, "pos": [0.5, 0.5], "vel": [0, 0]},
                                      {"id": 3, "pos": [1.0, 0.5]}]})");
    EXPECT_EQ(p.table_spec().length, 1.9812);
    EXPECT_EQ(p.balls().size(), 2u);
    EXPECT_EQ(p.game(), rules::Game::nine_ball) << "no ball above the 9";
    EXPECT_EQ(Practice::from_json(eight_ball().to_json()).game(), rules::Game::eight_ball);
}

TEST(Practice, BadPositionsAreRefusedByTheirField) {
    const std::string cue = R"({"id": 0, "pos": [0.5, 0.5]})";
    auto with = [&](const std::string& balls) { return R"({"balls": [)" + cue + balls + "]}"; };
    EXPECT_EQ(error_of(with(R"(, {"id": 4, "pos": [0.51, 0.5]})")),
              "position.balls[1].pos: The 4 can't go on top of the cue ball.");
    EXPECT_EQ(error_of(with(R"(, {"id": 4, "pos": [0.01, 0.5]})")),
              "position.balls[1].pos: The 4 must go on the cloth.");
    EXPECT_EQ(error_of(with(R"(, {"id": 0, "pos": [1.5, 0.5]})")),
              "position.balls[1].id: ball 0 is listed twice");
    EXPECT_NE(error_of(with(R"(, {"id": 16, "pos": [1.5, 0.5]})")).find("position.balls[1].id"),
              std::string::npos);
    EXPECT_EQ(error_of(with(R"(, {"id": 4, "pos": [1.5, 0.5], "vel": [1, 0]})")),
              "position.balls[1].vel: a position's balls are at rest: the velocity must be [0, 0] "
              "or left out");
    EXPECT_EQ(error_of(R"({"balls": [{"id": 3, "pos": [1.5, 0.5]}]})"),
              "position.balls: the cue ball (id 0) is missing");
    EXPECT_NE(error_of(R"({"balls": [], "rack": "8ball"})").find("rack"), std::string::npos);
    EXPECT_NE(error_of(R"({"table": "unbounded", "balls": []})").find("cushions"),
              std::string::npos);
    EXPECT_NE(error_of("{\"balls\": [").find("position"), std::string::npos);
}

}  // namespace
}  // namespace game::test
