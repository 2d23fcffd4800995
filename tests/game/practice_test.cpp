// Practice mode's state (game/practice.hpp, docs/game.md "Practice"): moving balls to legal
// places only, shots with pocketed balls leaving, try again, and a position saved as the
// `simulate` input that coolaaber-cli reads and that loads back to the same numbers.
#include "game/practice.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "../cli/cli_process.hpp"
#include "game/json_field.hpp"
#include "physics/markings.hpp"
#include "physics/simulate.hpp"

namespace game::test {
namespace {

Practice eight_ball() {
    return Practice(physics::RackType::eight_ball, physics::TableSpec{}, physics::Params{}, 3);
}

physics::Stroke break_stroke() {
    physics::Stroke s;
    s.speed = 8.0;
    s.heading_deg = 0.4;
    return s;
}

/// Checks each object ball `simulate` left on the table (`simulate_out`, its output) against the
/// practice's, bit for bit; returns how many it compared.
int same_object_balls(const Practice& p, const std::string& simulate_out) {
    int compared = 0;
    const nlohmann::json out = nlohmann::json::parse(simulate_out);
    for (const nlohmann::json& b : out.at("final")) {
        const int id = b.at("id").get<int>();
        if (b.at("pos").is_null() || id == 0) continue;
        ++compared;
        EXPECT_EQ(p.balls().at(id).x, b.at("pos")[0].get<double>()) << id;
        EXPECT_EQ(p.balls().at(id).y, b.at("pos")[1].get<double>()) << id;
    }
    return compared;
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
    const Practice nine(physics::RackType::nine_ball, physics::TableSpec{}, physics::Params{}, 3);
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
    EXPECT_GE(same_object_balls(played, r.out), 10) << "the object balls left after the break";
}

TEST(Practice, AFileForSimulateWithAPresetLoads) {
    const Practice p = Practice::from_json(
        R"({"table": "7ft", "balls": [{"id": 0, "pos": [0.5, 0.5], "vel": [0, 0]},
                                      {"id": 3, "pos": [1.0, 0.5]}]})");
    EXPECT_EQ(p.table_spec().length, 1.9812);
    EXPECT_EQ(p.balls().size(), 2u);
    EXPECT_EQ(p.game(), physics::RackType::nine_ball) << "no ball above the 9";
    EXPECT_EQ(Practice::from_json(eight_ball().to_json()).game(), physics::RackType::eight_ball);
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
    EXPECT_NE(error_of(with(R"(, {"id": 22, "pos": [1.5, 0.5]})")).find("position.balls[1].id"),
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

// ---- The snooker and three-cushion tables

namespace sb = physics::snooker_ball;
namespace cb = physics::carom_ball;

physics::Stroke stroke(double speed, double heading_deg) {
    physics::Stroke s;
    s.speed = speed;
    s.heading_deg = heading_deg;
    return s;
}

std::map<int, physics::Vec2> positions(const std::vector<physics::BallState>& balls) {
    std::map<int, physics::Vec2> out;
    for (const physics::BallState& b : balls) out[b.id] = b.pos;
    return out;
}

TEST(PracticeTables, SnookerStartsFromTheSetUpWithTheCueBallInTheD) {
    const Practice p = Practice::on_own_table(physics::RackType::snooker, 5);
    EXPECT_EQ(p.game(), physics::RackType::snooker);
    EXPECT_EQ(p.table_spec().length, physics::snooker_table_spec().length);
    EXPECT_TRUE(p.table_spec().pockets);
    EXPECT_EQ(p.params().ball_radius, physics::params_preset("snooker")->ball_radius);
    EXPECT_EQ(p.balls().size(), 22u);
    EXPECT_EQ(p.balls(), positions(physics::snooker_rack(p.table(), p.params())));
    EXPECT_TRUE(physics::snooker_markings(p.table()).in_d(p.balls().at(0)));
    EXPECT_EQ(p.return_words(), "in the D");
}

TEST(PracticeTables, ThreeCushionStartsFromTheStartingPosition) {
    const Practice p = Practice::on_own_table(physics::RackType::three_cushion, 5);
    EXPECT_EQ(p.game(), physics::RackType::three_cushion);
    EXPECT_FALSE(p.table_spec().pockets);
    EXPECT_EQ(p.params().ball_radius, physics::params_preset("carom")->ball_radius);
    EXPECT_EQ(p.balls(), positions(physics::carom_rack(p.table())));
    const physics::CaromSpots spots = physics::carom_spots(p.table());
    EXPECT_EQ(p.balls().at(cb::white), spots.start_right);
    EXPECT_EQ(p.balls().at(cb::red), spots.top);
}

TEST(PracticeTables, ATableMustSuitTheGame) {
    EXPECT_THROW(Practice(physics::RackType::three_cushion, physics::TableSpec{},
                          *physics::params_preset("carom"), 1),
                 std::invalid_argument)
        << "three-cushion has no pockets";
    EXPECT_THROW(Practice(physics::RackType::snooker, physics::carom_table_spec(),
                          *physics::params_preset("snooker"), 1),
                 std::invalid_argument);
}

TEST(PracticeTables, BallsMoveToLegalPlacesAndAreNamedAsPlayersNameThem) {
    Practice s = Practice::on_own_table(physics::RackType::snooker, 1);
    const physics::Vec2 pink = s.balls().at(sb::pink);
    EXPECT_EQ(s.check_move(3, pink), "The red can't go on top of the pink.");
    EXPECT_EQ(s.check_move(sb::black, {-0.1, 0.5}), "The black must go on the cloth.");
    EXPECT_EQ(s.check_move(0, s.balls().at(sb::brown)),
              "The cue ball can't go on top of the brown.");
    EXPECT_TRUE(s.move(sb::blue, {3.0, 0.3})) << "anywhere on the cloth: no spots in practice";
    EXPECT_EQ(s.balls().at(sb::blue), (physics::Vec2{3.0, 0.3}));
    EXPECT_TRUE(s.move(0, {2.5, 1.2})) << "the cue ball too, out of the D";

    Practice c = Practice::on_own_table(physics::RackType::three_cushion, 1);
    EXPECT_EQ(c.check_move(cb::yellow, c.balls().at(cb::red)),
              "The yellow can't go on top of the red.");
    EXPECT_EQ(c.check_move(cb::white, {1.0, 1.5}), "The white must go on the cloth.");
    EXPECT_FALSE(c.move(cb::red, c.balls().at(cb::white)));
    EXPECT_TRUE(c.move(cb::red, {2.0, 1.0}));
}

TEST(PracticeTables, SnookerPocketsARedAndTheCueBallComesBackInTheD) {
    Practice p = Practice::on_own_table(physics::RackType::snooker, 1);
    const physics::Vec2 home = p.balls().at(0);
    ASSERT_TRUE(p.move(1, {0.30, 0.30}));
    ASSERT_TRUE(p.move(0, {0.60, 0.60}));
    p.play(stroke(2.0, 225.0));  // the red straight into the SW corner
    EXPECT_FALSE(p.balls().count(1));
    EXPECT_EQ(p.balls().size(), 21u);

    ASSERT_TRUE(p.move(0, {0.20, 0.20}));
    const physics::Shot& in_off = p.play(stroke(1.5, 225.0));  // the cue ball alone, in SW
    ASSERT_EQ(in_off.final_states().front().motion, physics::Motion::pocketed);
    EXPECT_EQ(p.balls().at(0), home) << "back on the baulk line between brown and yellow";

    // Home taken: the free place in the D nearest it, touching no ball.
    p.try_again();
    ASSERT_TRUE(p.move(2, home));
    ASSERT_TRUE(p.move(0, {0.20, 0.20}));
    p.play(stroke(1.5, 225.0));
    const physics::Vec2 back = p.balls().at(0);
    EXPECT_TRUE(physics::snooker_markings(p.table()).in_d(back));
    EXPECT_GE(physics::norm(back - home), 2.0 * p.params().ball_radius);
    EXPECT_LT(physics::norm(back - home), 3.0 * p.params().ball_radius) << "the nearest place";
}

TEST(PracticeTables, ThreeCushionKeepsItsThreeBallsAndTriesAgain) {
    Practice p = Practice::on_own_table(physics::RackType::three_cushion, 1);
    const auto start = p.balls();
    p.play(stroke(6.0, 20.0));
    EXPECT_EQ(p.balls().size(), 3u) << "nothing leaves a table without pockets";
    EXPECT_NE(p.balls(), start);
    for (const auto& [id, pos] : p.balls())
        EXPECT_TRUE(p.table().on_surface(pos, p.params().ball_radius));
    p.try_again();
    EXPECT_EQ(p.balls(), start);
}

TEST(PracticeTables, SnookerAndCaromPositionsSaveAndLoadBackWithTheirGame) {
    for (physics::RackType game : {physics::RackType::snooker, physics::RackType::three_cushion}) {
        Practice p = Practice::on_own_table(game, 2);
        p.play(stroke(5.0, 3.0));
        const std::string saved = p.to_json();
        const Practice back = Practice::from_json(saved);
        EXPECT_EQ(back.game(), game);
        EXPECT_EQ(back.balls(), p.balls());
        EXPECT_EQ(back.params().ball_radius, p.params().ball_radius);
        EXPECT_EQ(back.to_json(), saved);
    }
}

TEST(PracticeTables, SimulatePlaysASavedSnookerPositionToTheSameEnd) {
    Practice p = Practice::on_own_table(physics::RackType::snooker, 2);
    nlohmann::json doc = nlohmann::json::parse(p.to_json());
    doc["strike"] = {{"speed", 6.0}, {"heading_deg", 1.0}};
    const cli_test::CliResult r = cli_test::run_cli("simulate", doc.dump());
    ASSERT_EQ(r.status, 0) << r.err;
    p.play(stroke(6.0, 1.0));
    EXPECT_GE(same_object_balls(p, r.out), 15);
}

TEST(PracticeTables, APositionsTableAndBallsSayWhoseGameItIs) {
    const std::string cue = R"({"id": 0, "pos": [0.7, 0.9]})";
    auto on = [&](const std::string& table, const std::string& balls) {
        return Practice::from_json(R"({"table": )" + table + R"(, "balls": [)" + cue + balls +
                                   "]}");
    };
    EXPECT_EQ(on(R"("snooker12ft")", R"(, {"id": 3, "pos": [2.0, 0.9]})").game(),
              physics::RackType::snooker)
        << "reds only, but the 12 ft table";
    EXPECT_EQ(on(R"("9ft")", R"(, {"id": 21, "pos": [2.0, 0.9]})").game(),
              physics::RackType::snooker)
        << "the black";
    EXPECT_EQ(on(R"({"preset": "carom10ft"})", R"(, {"id": 2, "pos": [2.0, 0.9]})").game(),
              physics::RackType::three_cushion);
    EXPECT_EQ(error_of(R"({"table": "carom10ft", "balls": [)" + cue +
                       R"(, {"id": 5, "pos": [2.0, 0.9]}]})"),
              "position.balls[1].id: a table without pockets holds the three-cushion balls: 0 "
              "(white), 1 (yellow), 2 (red); there is no ball 5");
    EXPECT_EQ(error_of(R"({"table": "snooker12ft", "balls": [)" + cue +
                       R"(, {"id": 17, "pos": [0.71, 0.9]}]})"),
              "position.balls[1].pos: The green can't go on top of the cue ball.");
}

}  // namespace
}  // namespace game::test
