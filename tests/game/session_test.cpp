// The session's flow through whole shots with the real physics: the break, ball in hand, calls,
// choices and re-racks, the 8, a 9-ball combination, the push-out, the three-foul rule,
// restart, determinism and resuming a saved game.
#include "game/session.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "game/random_player.hpp"
#include "physics/layout.hpp"
#include "session_support.hpp"

namespace game::test {
namespace {

using physics::PocketId;
using rules::CueBall;
using rules::Game;

const physics::Vec2 break_spot{L / 4.0 - 0.05, W / 2.0};

// Break strokes from `break_spot` at the apex ball, fanned out a little.
std::vector<physics::Stroke> break_strokes(std::vector<double> speeds) {
    return fan(0.0, {0.0, 0.3, -0.3, 0.6, -0.6, 0.9, -0.9, 1.2, -1.2}, std::move(speeds),
               {0.0, -0.2, 0.2});
}

TEST(Session, NewGameIsRackedAndWaitsForTheBreaker) {
    Session s(config_for(Game::eight_ball));
    EXPECT_EQ(s.phase(), Phase::place_cue_ball);
    EXPECT_EQ(s.to_act(), A);
    EXPECT_EQ(s.state().shot, rules::Shot::break_shot);
    EXPECT_EQ(s.ball_in_hand(), rules::BallInHand::kitchen);
    EXPECT_EQ(s.state().on_table.size(), 15u);
    EXPECT_EQ(s.state().positions.size(), 15u);  // no cue ball yet
    EXPECT_TRUE(s.pocketed().empty());
    EXPECT_TRUE(s.history().empty());
    EXPECT_EQ(s.last_shot(), nullptr);
    EXPECT_EQ(s.name(A), "Ann");
    EXPECT_EQ(s.name(B), "Bob");
    expect_consistent(s);

    Session nine(config_for(Game::nine_ball));
    EXPECT_EQ(nine.state().on_table.size(), 9u);
    // The 1 on the foot spot.
    EXPECT_DOUBLE_EQ(nine.state().positions.at(1).x, 3.0 * L / 4.0);
}

TEST(Session, RacksAreSeeded) {
    Session a(config_for(Game::eight_ball, 7)), b(config_for(Game::eight_ball, 7)),
        c(config_for(Game::eight_ball, 8));
    EXPECT_EQ(a.to_json(), b.to_json());
    EXPECT_NE(a.state().positions, c.state().positions);
}

TEST(Session, KitchenPlacement) {
    Session s(config_for(Game::eight_ball));
    EXPECT_THROW(s.play({5.0, 0.0}), Refused);  // the cue ball is not placed yet
    // In front of the head string, or on it: refused with the reason.
    for (double x : {L / 4.0 + 0.01, L / 4.0}) {
        try {
            s.place_cue_ball({x, W / 2.0});
            FAIL() << "placed at x = " << x;
        } catch (const Refused& e) {
            EXPECT_NE(std::string(e.what()).find("head string"), std::string::npos) << e.what();
        }
    }
    EXPECT_TRUE(s.check_cue_ball({-0.1, W / 2.0}));  // off the surface
    EXPECT_TRUE(s.check_cue_ball({0.3, R / 2.0}));   // into the cushion
    EXPECT_EQ(s.phase(), Phase::place_cue_ball);
    s.place_cue_ball({L / 4.0 - 0.01, W / 2.0});
    EXPECT_EQ(s.phase(), Phase::shoot);
    s.place_cue_ball(break_spot);  // may be moved again before the stroke
    EXPECT_DOUBLE_EQ(s.state().positions.at(0).x, break_spot.x);
    EXPECT_THROW(s.set_call(rules::Call::ball_in(3, pocket(PocketId::NE))), Refused);  // break
}

TEST(Session, BreakThatPocketsABallKeepsTheTable) {
    Session s(config_for(Game::eight_ball));
    s.place_cue_ball(break_spot);
    std::optional<physics::Stroke> k =
        find_stroke(s, break_strokes({8.0, 9.0, 7.0}), [](const ShotRecord& r) {
            return r.verdict.break_result == rules::BreakResult::legal && !r.verdict.foul &&
                   !r.summary.down.empty() && !down(r, 8) && !r.verdict.choice;
        });
    ASSERT_TRUE(k) << "no break stroke pockets a ball cleanly";

    const ShotRecord& r = s.play(*k);
    EXPECT_EQ(r.before.shot, rules::Shot::break_shot);
    EXPECT_EQ(r.shooter(), A);
    EXPECT_EQ(r.verdict.next_shooter, A);
    EXPECT_FALSE(r.verdict.turn_passes);
    EXPECT_EQ(s.phase(), Phase::shoot);
    EXPECT_EQ(s.to_act(), A);
    EXPECT_FALSE(s.state().group_a);  // the table is open after the break
    EXPECT_EQ(s.state().shot, rules::Shot::normal);
    ASSERT_EQ(s.pocketed().size(), r.summary.down.size());
    for (std::size_t i = 0; i < s.pocketed().size(); ++i) {
        EXPECT_EQ(s.pocketed()[i].ball, r.summary.down[i].ball);
        EXPECT_EQ(s.pocketed()[i].pocket, r.summary.down[i].pocket);
        EXPECT_EQ(s.pocketed()[i].by, A);
        EXPECT_FALSE(s.state().has(r.summary.down[i].ball));
    }
    ASSERT_NE(s.last_shot(), nullptr);
    EXPECT_EQ(s.last_shot()->events().size(), static_cast<std::size_t>(r.summary.events));
    EXPECT_GT(r.summary.duration, 0.0);
    EXPECT_TRUE(r.events.empty());  // keep_events is off
    EXPECT_EQ(s.history().size(), 1u);
    expect_consistent(s);
    // Balls are where the shot left them.
    for (const physics::BallState& b : s.last_shot()->final_states())
        if (b.motion != physics::Motion::pocketed) {
            ASSERT_TRUE(s.state().positions.count(b.id));
            EXPECT_NEAR(s.state().positions.at(b.id).x, b.pos.x, 1e-9);
            EXPECT_NEAR(s.state().positions.at(b.id).y, b.pos.y, 1e-9);
        }
}

TEST(Session, KeepEventsKeepsThePhysicsEvents) {
    Config c = config_for(Game::eight_ball);
    c.keep_events = true;
    Session s(c);
    s.place_cue_ball(break_spot);
    const ShotRecord& r = s.play({8.0, 0.0});
    EXPECT_EQ(r.events.size(), s.last_shot()->events().size());
    EXPECT_EQ(static_cast<int>(r.events.size()), r.summary.events);
}

TEST(Session, IllegalBreakOffersAChoiceAndReracks) {
    Session s(config_for(Game::eight_ball));
    s.place_cue_ball(break_spot);
    std::optional<physics::Stroke> k =
        find_stroke(s, break_strokes({0.6, 0.8, 1.0, 1.3}), [](const ShotRecord& r) {
            return r.verdict.break_result == rules::BreakResult::illegal && !r.verdict.foul;
        });
    ASSERT_TRUE(k) << "no soft break is illegal";
    const ShotRecord& r = s.play(*k);
    ASSERT_TRUE(r.verdict.choice);
    EXPECT_EQ(s.phase(), Phase::choose);
    EXPECT_EQ(s.to_act(), B);
    EXPECT_EQ(s.choice()->options,
              (std::vector{rules::ChoiceOption::accept_table, rules::ChoiceOption::rerack_and_break,
                           rules::ChoiceOption::rerack_offender_breaks}));
    // Nothing else may happen while the choice is pending.
    EXPECT_THROW(s.play({2.0, 0.0}), Refused);
    EXPECT_THROW(s.set_call(rules::Call::safety()), Refused);
    EXPECT_TRUE(s.check_cue_ball({0.3, 0.3}));
    EXPECT_THROW(s.choose(rules::ChoiceOption::shoot), Refused);  // not offered

    const auto rack0 = s.state().positions;
    s.choose(rules::ChoiceOption::rerack_and_break);
    EXPECT_EQ(s.history().back().choice, rules::ChoiceOption::rerack_and_break);
    EXPECT_EQ(s.rack_number(), 1);
    EXPECT_EQ(s.phase(), Phase::place_cue_ball);
    EXPECT_EQ(s.to_act(), B);
    EXPECT_EQ(s.state().breaker, B);
    EXPECT_EQ(s.state().shot, rules::Shot::break_shot);
    EXPECT_EQ(s.state().on_table.size(), 15u);
    EXPECT_TRUE(s.pocketed().empty());
    EXPECT_NE(s.state().positions, rack0);  // a new rack (another seed)
    EXPECT_THROW(s.choose(rules::ChoiceOption::accept_table), Refused);  // no choice now
    expect_consistent(s);
}

// A break (cue ball in hand in the kitchen) at a hand-made table: the 8 lies in front of the N
// side pocket, outside the kitchen, and three balls lie near the foot cushion.
TableState eight_by_the_side_pocket() {
    TableState t;
    t.shot = "break";
    t.cue_ball = "in_hand_kitchen";
    t.balls = {{8, {L / 2.0 - 0.2, W - 0.3}}, {1, {2.2, 0.3}}, {10, {2.2, 0.6}}, {12, {2.2, 0.9}}};
    return t;
}

TEST(Session, EightOnTheBreakOffersSpotOrRebreakToTheBreaker) {
    Session s = session_with(config_for(Game::eight_ball), eight_by_the_side_pocket());
    ASSERT_EQ(s.phase(), Phase::place_cue_ball);
    EXPECT_EQ(s.ball_in_hand(), rules::BallInHand::kitchen);
    // The cue ball 0.85 m behind the 8 on the line from the N pocket through it.
    const physics::Vec2 eight = s.state().positions.at(8);
    const physics::Vec2 mouth{L / 2.0, W};
    const physics::Vec2 dir = (1.0 / physics::norm(mouth - eight)) * (mouth - eight);
    const physics::Vec2 cue = eight - 0.85 * dir;
    ASSERT_LT(cue.x, L / 4.0);
    s.place_cue_ball(cue);
    const double at = heading(cue, eight);
    std::optional<physics::Stroke> k = find_stroke(
        s, fan(at, {0.0, 0.5, -0.5, 1.0, -1.0, 1.5, -1.5}, {2.0, 3.0, 1.5}, {0.0, -0.3}),
        [](const ShotRecord& r) {
            return pocket_of(r, 8) == pocket(PocketId::N) && !down(r, 0) &&
                   r.summary.first_contact == 8;
        });
    ASSERT_TRUE(k) << "no stroke pots the 8 in the N pocket";
    const ShotRecord& r = s.play(*k);
    // A legal break (a ball was pocketed), no foul, and the breaker's choice.
    EXPECT_EQ(r.verdict.break_result, rules::BreakResult::legal);
    EXPECT_FALSE(r.verdict.foul);
    EXPECT_FALSE(r.verdict.game_over);
    ASSERT_EQ(s.phase(), Phase::choose);
    EXPECT_EQ(s.to_act(), A);
    EXPECT_EQ(s.choice()->options, (std::vector{rules::ChoiceOption::spot_8_and_continue,
                                                rules::ChoiceOption::rebreak}));
    const Session pending = s;

    // Spot the 8 and go on: the 8 is back on the foot spot, A shoots from where the cue ball
    // lies, the table is open.
    s.choose(rules::ChoiceOption::spot_8_and_continue);
    EXPECT_EQ(s.phase(), Phase::shoot);
    EXPECT_EQ(s.to_act(), A);
    ASSERT_TRUE(s.state().has(8));
    EXPECT_DOUBLE_EQ(s.state().positions.at(8).x, 3.0 * L / 4.0);
    EXPECT_DOUBLE_EQ(s.state().positions.at(8).y, W / 2.0);
    EXPECT_FALSE(s.state().group_a);
    EXPECT_EQ(s.ball_in_hand(), rules::BallInHand::none);
    for (const Pocketed& p : s.pocketed()) EXPECT_NE(p.ball, 8);
    expect_consistent(s);

    // Or break again: a full rack, A breaks from the kitchen.
    Session again = pending;
    again.choose(rules::ChoiceOption::rebreak);
    EXPECT_EQ(again.rack_number(), 1);
    EXPECT_EQ(again.phase(), Phase::place_cue_ball);
    EXPECT_EQ(again.to_act(), A);
    EXPECT_EQ(again.state().breaker, A);
    EXPECT_EQ(again.state().shot, rules::Shot::break_shot);
    EXPECT_EQ(again.state().on_table.size(), 15u);
    EXPECT_TRUE(again.pocketed().empty());
    EXPECT_EQ(again.ball_in_hand(), rules::BallInHand::kitchen);
    expect_consistent(again);
}

TEST(Session, NineOnAFoulIsRespottedAndTheOtherBallsStayDown) {
    // A must hit the 3 first, but the 9 lies straight in front of the cue ball, on the diagonal
    // into the NE pocket: potting it is a foul (wrong ball first) and the 9 comes back up.
    TableState t;
    const physics::Vec2 nine{L - 0.35, W - 0.35};
    t.balls = {{0, {nine.x - 0.4, nine.y - 0.4}}, {3, {0.5, 0.3}}, {9, nine}};
    Session s = session_with(config_for(Game::nine_ball), t);
    std::optional<physics::Stroke> k =
        find_stroke(s, fan(45.0, {0.0, 0.2, -0.2, 0.4, -0.4}, {1.5, 2.0, 2.5}, {-0.3, 0.0}),
                    [](const ShotRecord& r) { return down(r, 9) && !down(r, 0); });
    ASSERT_TRUE(k);
    const ShotRecord& r = s.play(*k);
    EXPECT_TRUE(r.verdict.has(rules::Foul::wrong_ball_first));
    EXPECT_FALSE(r.verdict.game_over);
    EXPECT_EQ(r.verdict.respot, std::vector<int>{9});
    EXPECT_EQ(s.winner(), std::nullopt);
    EXPECT_EQ(s.to_act(), B);
    EXPECT_EQ(s.ball_in_hand(), rules::BallInHand::anywhere);
    ASSERT_TRUE(s.state().has(9));
    EXPECT_DOUBLE_EQ(s.state().positions.at(9).x, 3.0 * L / 4.0);  // the foot spot was free
    EXPECT_DOUBLE_EQ(s.state().positions.at(9).y, W / 2.0);
    for (const Pocketed& p : s.pocketed()) EXPECT_NE(p.ball, 9);
    expect_consistent(s);
}

TEST(Session, ScratchGivesBallInHandAnywhere) {
    // Open table after the break; A's cue ball near the SW pocket, nothing in the way.
    TableState t;
    t.balls = {{0, {0.25, 0.25}}, {3, {1.5, 0.6}}, {8, {2.0, 0.7}}, {12, {1.0, 1.0}}};
    Session s = session_with(config_for(Game::eight_ball), t);
    s.set_call(rules::Call::ball_in(3, pocket(PocketId::SE)));
    std::optional<physics::Stroke> k =
        find_stroke(s, fan(225.0, {0.0, 1.0, -1.0, 2.0, -2.0}, {1.0, 2.0}, {0.0}),
                    [](const ShotRecord& r) { return r.verdict.has(rules::Foul::scratch); });
    ASSERT_TRUE(k);
    const ShotRecord& r = s.play(*k);
    EXPECT_EQ(r.before.call, rules::Call::ball_in(3, pocket(PocketId::SE)));
    EXPECT_EQ(r.verdict.fouls, (std::vector{rules::Foul::scratch, rules::Foul::no_contact}));
    EXPECT_TRUE(s.state().call == rules::Call::nothing());  // a call lasts one shot
    EXPECT_EQ(s.to_act(), B);
    EXPECT_EQ(s.phase(), Phase::place_cue_ball);
    EXPECT_EQ(s.ball_in_hand(), rules::BallInHand::anywhere);
    EXPECT_FALSE(s.state().positions.count(0));
    EXPECT_EQ(s.state().fouls_in_row[0], 1);

    // Illegal placements, each with its reason; the session is unchanged.
    const std::string before = s.to_json();
    auto refused = [&](physics::Vec2 p, const std::string& reason) {
        try {
            s.place_cue_ball(p);
            ADD_FAILURE() << "placed at " << p.x << ", " << p.y;
        } catch (const Refused& e) {
            EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
        }
    };
    refused({1.5, 0.6}, "overlap ball 3");
    refused({1.5 + 2 * R - 1e-6, 0.6}, "overlap ball 3");
    refused({-0.2, 0.5}, "off the playing surface");
    refused({1.0, W}, "off the playing surface");
    refused({std::nan(""), 0.5}, "finite");
    EXPECT_EQ(s.to_json(), before);
    EXPECT_THROW(s.play({2.0, 0.0}), Refused);

    // Anywhere means anywhere: in front of the head string, touching a ball (frozen) too.
    s.place_cue_ball({2.3, 1.1});
    EXPECT_EQ(s.phase(), Phase::shoot);
    s.place_cue_ball({1.5 + 2 * R, 0.6});
    EXPECT_EQ(s.phase(), Phase::shoot);
    expect_consistent(s);
    s.play({1.0, 0.0});  // B shoots from the placed spot
    EXPECT_DOUBLE_EQ(s.history().back().before.positions.at(0).x, 1.5 + 2 * R);
}

TEST(Session, CallsAreChecked) {
    TableState t;
    t.groups = {{"A", "solids"}, {"B", "stripes"}};
    t.balls = {{0, {0.5, 0.6}}, {2, {1.5, 0.3}}, {8, {2.0, 0.7}}, {12, {1.0, 1.0}}};
    Session s = session_with(config_for(Game::eight_ball), t);
    EXPECT_THROW(s.set_call(rules::Call::ball_in(8, pocket(PocketId::NE))), Refused);  // 2 is up
    EXPECT_THROW(s.set_call(rules::Call::ball_in(5, pocket(PocketId::NE))), Refused);  // down
    EXPECT_THROW(s.set_call(rules::Call::ball_in(2, 6)), Refused);
    s.set_call(rules::Call::ball_in(12, pocket(PocketId::N)));  // legal, though not his ball
    s.set_call(rules::Call::safety());
    EXPECT_TRUE(s.state().call.is_safety());

    Session nine(config_for(Game::nine_ball));
    EXPECT_THROW(nine.set_call(rules::Call::safety()), Refused);
    nine.set_call(rules::Call::nothing());
}

// A: solids cleared, on the 8; the 8 lies on the diagonal into the NE pocket.
TableState on_the_eight() {
    TableState t;
    t.groups = {{"A", "solids"}, {"B", "stripes"}};
    const physics::Vec2 eight{L - 0.35, W - 0.35};
    t.balls = {{0, {eight.x - 0.4, eight.y - 0.4}}, {8, eight}, {9, {0.5, 0.3}}, {10, {0.5, 1.0}}};
    return t;
}

TEST(Session, WinOnTheEight) {
    Session s = session_with(config_for(Game::eight_ball), on_the_eight());
    const rules::Call call = rules::Call::ball_in(8, pocket(PocketId::NE));
    std::optional<physics::Stroke> k = find_stroke(
        s, fan(45.0, {0.0, 0.2, -0.2, 0.4, -0.4}, {1.5, 2.0, 2.5, 3.0}, {-0.3, 0.0, -0.5}),
        [](const ShotRecord& r) {
            return pocket_of(r, 8) == pocket(PocketId::NE) && !down(r, 0) && !r.verdict.foul;
        },
        [&](Session& trial) { trial.set_call(call); });
    ASSERT_TRUE(k);
    s.set_call(call);
    const ShotRecord& r = s.play(*k);
    EXPECT_TRUE(r.verdict.game_over);
    EXPECT_EQ(s.phase(), Phase::game_over);
    EXPECT_EQ(s.winner(), A);
    EXPECT_EQ(s.to_act(), std::nullopt);
    EXPECT_EQ(s.score(), (std::array{1, 0}));
    EXPECT_FALSE(s.state().has(8));
    EXPECT_EQ(s.pocketed().back().ball, 8);
    expect_consistent(s);
    EXPECT_THROW(s.play(*k), Refused);
    EXPECT_THROW(s.declare_stalemate(), Refused);

    // The same stroke with the 8 called in another pocket loses.
    Session other = session_with(config_for(Game::eight_ball), on_the_eight());
    other.set_call(rules::Call::ball_in(8, pocket(PocketId::N)));
    other.play(*k);
    EXPECT_EQ(other.winner(), B);

    // A finished game saves and loads.
    EXPECT_EQ(Session::from_json(s.to_json()).to_json(), s.to_json());

    // The next game: B breaks (breaks alternate), the score stays.
    s.restart();
    EXPECT_EQ(s.game_number(), 1);
    EXPECT_EQ(s.phase(), Phase::place_cue_ball);
    EXPECT_EQ(s.to_act(), B);
    EXPECT_EQ(s.state().breaker, B);
    EXPECT_EQ(s.state().on_table.size(), 15u);
    EXPECT_TRUE(s.history().empty());
    EXPECT_TRUE(s.pocketed().empty());
    EXPECT_EQ(s.winner(), std::nullopt);
    EXPECT_EQ(s.score(), (std::array{1, 0}));
    EXPECT_EQ(s.last_shot(), nullptr);
}

TEST(Session, EarlyEightLoses) {
    TableState t = on_the_eight();
    t.balls[3] = {0.9, 0.3};  // A still has a solid on the table
    Session s = session_with(config_for(Game::eight_ball), t);
    s.set_call(rules::Call::ball_in(3, pocket(PocketId::SW)));
    std::optional<physics::Stroke> k = find_stroke(
        s, fan(45.0, {0.0, 0.2, -0.2, 0.4, -0.4}, {1.5, 2.0, 2.5, 3.0}, {-0.3, 0.0, -0.5}),
        [](const ShotRecord& r) { return down(r, 8) && !down(r, 0); },
        [](Session& trial) { trial.set_call(rules::Call::ball_in(3, pocket(PocketId::SW))); });
    ASSERT_TRUE(k);
    const ShotRecord& r = s.play(*k);
    EXPECT_TRUE(r.verdict.game_over);
    EXPECT_TRUE(r.verdict.has(rules::Foul::wrong_ball_first));
    EXPECT_EQ(s.winner(), B);
    EXPECT_EQ(s.score(), (std::array{0, 1}));
    expect_consistent(s);
}

TEST(Session, NineBallCombinationWins) {
    TableState t;
    const physics::Vec2 nine{L - 0.3, W - 0.3};
    const double c = std::sqrt(0.5);
    const physics::Vec2 one{nine.x - 0.2 * c, nine.y - 0.2 * c};
    t.balls = {{0, {one.x - 0.4 * c, one.y - 0.4 * c}}, {1, one}, {5, {0.5, 0.3}}, {9, nine}};
    Session s = session_with(config_for(Game::nine_ball), t);
    std::optional<physics::Stroke> k =
        find_stroke(s, fan(45.0, {0.0, 0.2, -0.2, 0.4, -0.4}, {2.0, 3.0, 4.0}, {-0.3, 0.0}),
                    [](const ShotRecord& r) { return down(r, 9) && !down(r, 0) && !down(r, 1); });
    ASSERT_TRUE(k);
    const ShotRecord& r = s.play(*k);
    EXPECT_EQ(r.summary.first_contact, 1);
    EXPECT_FALSE(r.verdict.foul);
    EXPECT_TRUE(r.verdict.game_over);
    EXPECT_EQ(s.winner(), A);
    expect_consistent(s);
}

// 9-ball right after a foul-free break: A may push out.
TableState after_break() {
    TableState t;
    t.shot = "after_break";
    t.balls = {{0, {0.6, 0.6}}, {1, {1.8, 0.4}}, {4, {2.0, 0.9}}, {9, {1.2, 1.0}}};
    return t;
}

TEST(Session, PushOutThenShootOrPassBack) {
    Session s = session_with(config_for(Game::nine_ball), after_break());
    EXPECT_TRUE(s.push_out_available());
    s.set_push_out(true);
    EXPECT_EQ(s.state().shot, rules::Shot::push_out);
    s.set_push_out(false);  // withdrawn
    EXPECT_EQ(s.state().shot, rules::Shot::after_break);
    s.set_push_out(true);
    // A soft roll towards the head cushion: touches no ball, which a push-out allows.
    const ShotRecord& r = s.play({0.8, 180.0});
    EXPECT_TRUE(r.push_out());
    EXPECT_FALSE(r.verdict.foul);
    EXPECT_FALSE(r.summary.first_contact);
    ASSERT_EQ(s.phase(), Phase::choose);
    EXPECT_EQ(s.to_act(), B);
    EXPECT_EQ(s.choice()->options,
              (std::vector{rules::ChoiceOption::shoot, rules::ChoiceOption::pass_back}));
    const Session pending = s;

    s.choose(rules::ChoiceOption::shoot);
    EXPECT_EQ(s.phase(), Phase::shoot);
    EXPECT_EQ(s.to_act(), B);
    EXPECT_EQ(s.state().shot, rules::Shot::after_push_out);
    EXPECT_FALSE(s.push_out_available());
    EXPECT_THROW(s.set_push_out(true), Refused);

    Session back = pending;
    back.choose(rules::ChoiceOption::pass_back);
    EXPECT_EQ(back.to_act(), A);
    EXPECT_EQ(back.state().shot, rules::Shot::after_push_out);
    EXPECT_EQ(back.history().back().choice, rules::ChoiceOption::pass_back);
    expect_consistent(back);

    // A pending choice saves and loads, and goes on the same way.
    Session loaded = Session::from_json(pending.to_json());
    EXPECT_EQ(loaded.phase(), Phase::choose);
    loaded.choose(rules::ChoiceOption::pass_back);
    EXPECT_EQ(loaded.to_json(), back.to_json());
}

TEST(Session, PushOutOnlyRightAfterTheBreak) {
    TableState t = after_break();
    t.shot = "normal";
    Session s = session_with(config_for(Game::nine_ball), t);
    EXPECT_FALSE(s.push_out_available());
    EXPECT_THROW(s.set_push_out(true), Refused);
    Session eight(config_for(Game::eight_ball));
    EXPECT_THROW(eight.set_push_out(true), Refused);
}

TEST(Session, ThreeFoulWarningAndLoss) {
    TableState t = after_break();
    t.shot = "normal";
    t.fouls = {1, 0};
    Session s = session_with(config_for(Game::nine_ball), t);
    EXPECT_FALSE(s.warned(A));
    s.play({0.8, 180.0});  // no contact: A's second foul in a row
    EXPECT_TRUE(s.warned(A));
    EXPECT_EQ(s.state().fouls_in_row[0], 2);
    EXPECT_EQ(s.to_act(), B);
    EXPECT_EQ(s.ball_in_hand(), rules::BallInHand::anywhere);

    t.fouls = {2, 0};
    t.warned = {true, false};
    Session third = session_with(config_for(Game::nine_ball), t);
    const ShotRecord& r = third.play({0.8, 180.0});
    EXPECT_TRUE(r.verdict.has(rules::Foul::third_consecutive_foul));
    EXPECT_EQ(third.winner(), B);
}

TEST(Session, StalemateReracksForTheOriginalBreaker) {
    TableState t = after_break();
    t.breaker = B;
    Session s = session_with(config_for(Game::nine_ball), t);
    s.declare_stalemate();
    EXPECT_EQ(s.rack_number(), 1);
    EXPECT_EQ(s.to_act(), B);
    EXPECT_EQ(s.state().shot, rules::Shot::break_shot);
    EXPECT_EQ(s.state().on_table.size(), 9u);
    expect_consistent(s);
}

// A break with the 1 in front of the SW corner pocket and the cue ball straight behind it: with
// follow, both drop. A legal break (a ball down) and a scratch.
TableState scratch_on_a_legal_break() {
    TableState t;
    t.shot = "break";
    t.cue_ball = "in_hand_kitchen";
    t.balls = {{1, {0.15, 0.15}}, {2, {2.0, 0.3}}, {8, {2.0, 0.6}}, {12, {2.0, 0.9}}};
    return t;
}

TEST(Session, NoChoiceWhereTheOptionsLeadToTheSamePosition) {
    Session s = session_with(config_for(Game::eight_ball), scratch_on_a_legal_break());
    const physics::Vec2 cue{0.45, 0.45};
    s.place_cue_ball(cue);
    std::optional<physics::Stroke> k =
        find_stroke(s, fan(heading(cue, {0.15, 0.15}), {0.0}, {1.0, 1.5, 2.0}, {0.0, 0.4}),
                    [](const ShotRecord& r) { return down(r, 1) && down(r, 0); });
    ASSERT_TRUE(k) << "no stroke pots the 1 and follows it in";
    const ShotRecord& r = s.play(*k);
    EXPECT_EQ(r.verdict.break_result, rules::BreakResult::legal);
    ASSERT_TRUE(r.verdict.has(rules::Foul::scratch));
    // The rules offer "the table as it lies" or "ball in hand in the kitchen": with the cue
    // ball pocketed both are ball in hand in the kitchen for Bob, so nothing is asked.
    ASSERT_TRUE(r.verdict.choice);
    EXPECT_EQ(r.verdict.choice->options, (std::vector{rules::ChoiceOption::accept_table,
                                                      rules::ChoiceOption::kitchen_ball_in_hand}));
    EXPECT_EQ(s.phase(), Phase::place_cue_ball);
    EXPECT_FALSE(s.choice());
    EXPECT_EQ(s.to_act(), B);
    EXPECT_EQ(s.ball_in_hand(), rules::BallInHand::kitchen);
    EXPECT_EQ(s.history().back().choice, rules::ChoiceOption::accept_table);
    expect_consistent(s);
    // The session saves and loads as it is.
    EXPECT_EQ(Session::from_json(s.to_json()).to_json(), s.to_json());
}

TEST(Session, RestartBeforeTheFirstShotRacksTheSameGameAgain) {
    Session s(config_for(Game::eight_ball));
    const auto rack = s.state().positions;
    s.place_cue_ball(break_spot);
    s.restart();
    EXPECT_EQ(s.game_number(), 0);
    EXPECT_EQ(s.to_act(), A);  // the break is not given away
    EXPECT_EQ(s.phase(), Phase::place_cue_ball);
    EXPECT_EQ(s.state().positions, rack);
    s.place_cue_ball(break_spot);
    s.play({8.0, 0.0});
    s.restart();  // after a shot: the next game, the other breaker
    EXPECT_EQ(s.game_number(), 1);
    EXPECT_EQ(s.to_act(), B);
}

TEST(Session, StrokesAreChecked) {
    TableState t = after_break();
    Session s = session_with(config_for(Game::nine_ball), t);
    EXPECT_THROW(s.play({-1.0, 0.0}), Refused);
    EXPECT_THROW(s.play({25.0, 0.0}), Refused);
    EXPECT_THROW(s.play({2.0, std::nan("")}), Refused);
    EXPECT_THROW(s.play({2.0, 0.0, 1.5}), Refused);
    EXPECT_THROW(s.play({2.0, 0.0, 0.0, 0.0, -5.0}), Refused);
    EXPECT_TRUE(s.history().empty());
}

// Replays the recorded shots `from`.. of `record` on `s`.
void replay(Session& s, const std::vector<ShotRecord>& record, std::size_t from) {
    if (s.phase() == Phase::choose) s.choose(*record.at(from - 1).choice);
    for (std::size_t i = from; i < record.size(); ++i) {
        const ShotRecord& r = record[i];
        if (s.phase() == Phase::place_cue_ball) s.place_cue_ball(r.before.positions.at(0));
        s.set_call(r.before.call);
        if (r.push_out()) s.set_push_out(true);
        s.play(r.stroke);
        if (r.choice && s.phase() == Phase::choose) s.choose(*r.choice);
    }
}

TEST(Session, SameActionsSameGame) {
    for (Game g : {Game::eight_ball, Game::nine_ball}) {
        Session s(config_for(g, 11)), t(config_for(g, 11));
        RandomPlayer a1(1), b1(2), a2(1), b2(2);
        play_shots(s, a1, b1, 40);
        play_shots(t, a2, b2, 40);
        EXPECT_EQ(s.to_json(), t.to_json());
    }
}

TEST(Session, ResumedGameGoesOnIdentically) {
    for (Game g : {Game::eight_ball, Game::nine_ball}) {
        for (std::uint64_t seed : {3u, 4u, 5u}) {
            Session s(config_for(g, seed));
            RandomPlayer a(seed * 2 + 1), b(seed * 2 + 2);
            play_shots(s, a, b, 6);
            const std::string saved = s.to_json();
            const std::size_t at = s.history().size();
            play_shots(s, a, b, 30);

            Session resumed = Session::from_json(saved);
            EXPECT_EQ(resumed.to_json(), saved);
            replay(resumed, s.history(), at);
            EXPECT_EQ(resumed.to_json(), s.to_json()) << rules::name(g) << " seed " << seed;
        }
    }
}

}  // namespace
}  // namespace game::test
