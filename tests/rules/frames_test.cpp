// Whole snooker frames and three-cushion games played by a random player through the real
// physics: every stroke ends, every verdict keeps the scores and the table consistent, and
// every frame and game ends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "physics/layout.hpp"
#include "physics/markings.hpp"
#include "physics/rack.hpp"
#include "physics/simulate.hpp"
#include "physics/table.hpp"
#include "rules/snooker.hpp"
#include "rules/three_cushion.hpp"

namespace rules {
namespace {

using physics::BallState;
using physics::SplitMix64;
using physics::Vec2;
namespace sb = physics::snooker_ball;

bool free_at(const std::map<int, Vec2>& pos, Vec2 p, double R) {
    for (const auto& [id, q] : pos)
        if (physics::norm(q - p) < 2 * R) return false;
    return true;
}

/// A stroke at a random ball among `targets`, a little off the full ball, at a random speed.
physics::Stroke aim(const std::map<int, Vec2>& pos, int cue, const std::vector<int>& targets,
                    SplitMix64& rng) {
    physics::Stroke s;
    s.ball = cue;
    s.speed = 1.0 + 6.0 * rng.uniform();
    const Vec2 to = pos.at(targets[rng.below(targets.size())]) - pos.at(cue);
    s.heading_deg =
        std::atan2(to.y, to.x) * 180.0 / std::numbers::pi + 20.0 * (rng.uniform() - 0.5);
    s.side = 0.6 * (rng.uniform() - 0.5);
    s.top = 0.6 * (rng.uniform() - 0.5);
    return s;
}

struct SnookerRun {
    int strokes = 0;
    bool over = false;
};

/// The balls a random snooker player aims at: a ball on (any colour when a colour is on).
std::vector<int> snooker_targets(const SnookerState& s) {
    std::vector<int> t;
    const BallOn on = ball_on(s);
    for (int id : s.on_table) {
        const bool want = on == BallOn::red      ? physics::is_red(id)
                          : on == BallOn::colour ? physics::is_colour(id)
                                                 : id == sb::yellow + static_cast<int>(on) -
                                                             static_cast<int>(BallOn::yellow);
        if (want && s.positions.count(id)) t.push_back(id);
    }
    if (t.empty())
        for (int id : s.on_table) t.push_back(id);
    return t;
}

void place_in_d(SnookerState& s, const physics::SnookerMarkings& m, double R, SplitMix64& rng) {
    for (;;) {
        const double a = std::numbers::pi * (0.5 + rng.uniform()), r = m.d_radius * rng.uniform();
        const Vec2 p = m.d_centre() + Vec2{r * std::cos(a), r * std::sin(a)};
        if (p.x >= R && free_at(s.positions, p, R)) {
            s.positions[0] = p;
            s.cue_ball = CueBall::on_table;
            return;
        }
    }
}

// Checks one verdict against the state it came from and the shot's final positions.
void check_snooker(const SnookerState& s, const SnookerVerdict& v, const physics::Shot& shot,
                   const physics::Table& t, const physics::Params& p) {
    const Player striker = s.shooter, opponent = other(s.shooter);
    EXPECT_EQ(v.state.score(striker), s.score(striker) + v.points_scored);
    EXPECT_EQ(v.state.score(opponent), s.score(opponent) + v.foul_points);
    if (v.foul) {
        EXPECT_EQ(v.points_scored, 0);
        EXPECT_GE(v.foul_points, 4);
        EXPECT_LE(v.foul_points, 7);
        if (!v.respotted_black) {
            EXPECT_LE(points_remaining(v.state), points_remaining(s));
        }
    } else {
        EXPECT_EQ(v.foul_points, 0);
        if (!s.free_ball && !v.respotted_black) {
            EXPECT_LE(v.points_scored, points_remaining(s) - points_remaining(v.state));
        }
    }
    EXPECT_LE(v.state.reds(), s.reds());
    if (v.state.reds() > 0)
        for (int c = sb::yellow; c <= sb::black; ++c) {
            EXPECT_TRUE(v.state.has(c)) << c;
        }
    if (v.frame_over) return;
    // Balls not re-spotted lie where the physics left them; the table is a valid layout.
    for (const BallState& b : shot.final_states()) {
        const bool respotted = std::any_of(v.respotted.begin(), v.respotted.end(),
                                           [&](const Respot& r) { return r.ball == b.id; });
        if (b.motion == physics::Motion::pocketed || respotted || !v.state.positions.count(b.id))
            continue;
        EXPECT_EQ(v.state.positions.at(b.id), b.pos) << b.id;
    }
    EXPECT_FALSE(physics::validate_layout(t, p, physics::balls_at_rest(v.state.positions)));
    for (int id : v.state.on_table) {
        EXPECT_TRUE(v.state.positions.count(id)) << id;
    }
}

SnookerRun play_frame(std::uint64_t seed, int cap) {
    const physics::Params p = *physics::params_preset("snooker");
    const physics::Table t = physics::build_table(physics::snooker_table_spec());
    const SnookerTable table{physics::snooker_markings(t), p.ball_radius};
    SplitMix64 rng(seed);
    SnookerState s;
    s.cue_ball = CueBall::on_table;
    for (const BallState& b : physics::snooker_rack(t, p)) {
        s.positions[b.id] = b.pos;
        if (b.id != 0) s.on_table.insert(b.id);
    }
    SnookerRun run;
    for (; run.strokes < cap && !run.over; ++run.strokes) {
        if (s.cue_ball == CueBall::in_hand) place_in_d(s, table.marks, p.ball_radius, rng);
        const std::vector<int> targets = snooker_targets(s);
        if (s.colour_on) s.nominated = targets[rng.below(targets.size())];
        if (s.free_ball) s.nominated = *s.on_table.rbegin();
        const physics::Stroke stroke = aim(s.positions, 0, targets, rng);
        const std::vector<BallState> balls = physics::balls_at_rest(s.positions);
        const physics::Shot shot = physics::simulate(t, p, balls, &stroke);
        EXPECT_FALSE(shot.truncated());
        const SnookerVerdict v = judge_snooker({}, table, s, shot.events());
        check_snooker(s, v, shot, t, p);
        if (::testing::Test::HasFailure()) return run;
        run.over = v.frame_over;
        if (run.over) {
            EXPECT_EQ(v.winner,
                      v.state.score(Player::A) > v.state.score(Player::B) ? Player::A : Player::B);
        }
        s = v.state;
        if (!s.free_ball) s.nominated.reset();
    }
    return run;
}

TEST(SnookerFrames, RandomPlayerFinishesFrames) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const SnookerRun run = play_frame(seed, 4000);
        EXPECT_TRUE(run.over) << "seed " << seed << ": not over after " << run.strokes;
        std::printf("snooker frame seed %llu: %d strokes\n", static_cast<unsigned long long>(seed),
                    run.strokes);
    }
}

/// Whether the events make a three-cushion point for `cue`, counted independently.
bool is_point(std::span<const physics::Event> events, int cue) {
    std::set<int> met;
    int cushions = 0;
    for (const physics::Event& e : events) {
        if (e.type == physics::EventType::cushion && e.ball(0) == cue && met.size() < 2) ++cushions;
        if (e.type == physics::EventType::ball_ball && e.involves(cue)) {
            met.insert(e.ball(0) == cue ? e.ball(1) : e.ball(0));
            if (met.size() == 2) return cushions >= 3;
        }
    }
    return false;
}

TEST(CaromGames, RandomPlayerFinishesGames) {
    const physics::Params p = *physics::params_preset("carom");
    const physics::Table t = physics::build_table(physics::carom_table_spec());
    const physics::CaromSpots spots = physics::carom_spots(t);
    const CaromOptions options{.target = 3, .equal_innings = true};
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        SplitMix64 rng(seed);
        CaromState s;
        for (const BallState& b : physics::carom_rack(t)) s.positions[b.id] = b.pos;
        bool over = false;
        int strokes = 0;
        for (; strokes < 20000 && !over; ++strokes) {
            const int cue = s.cue_ball(s.shooter);
            std::vector<int> targets;
            for (int id = 0; id <= 2; ++id)
                if (id != cue) targets.push_back(id);
            physics::Stroke stroke = aim(s.positions, cue, targets, rng);
            stroke.heading_deg += 360.0 * rng.uniform();  // any heading: banks first too
            stroke.heading_deg = std::fmod(stroke.heading_deg, 360.0);
            const physics::Shot shot =
                physics::simulate(t, p, physics::balls_at_rest(s.positions), &stroke);
            ASSERT_FALSE(shot.truncated());
            const CaromVerdict v =
                judge_three_cushion(options, spots, p.ball_radius, s, shot.events());
            EXPECT_FALSE(std::find(v.fouls.begin(), v.fouls.end(), CaromFoul::wrong_cue_ball) !=
                         v.fouls.end());
            if (!v.foul) {
                EXPECT_EQ(v.point, is_point(shot.events(), cue));
            }
            const int gained = v.state.scores[index(s.shooter)] - s.scores[index(s.shooter)];
            EXPECT_EQ(gained, v.point ? 1 : 0);
            EXPECT_EQ(v.state.scores[index(other(s.shooter))], s.scores[index(other(s.shooter))]);
            const bool equalizing_starts = v.state.equalizing && !s.equalizing;
            if (!v.game_over && !equalizing_starts) {
                EXPECT_EQ(*v.next_shooter == s.shooter, v.point);
            }
            if (equalizing_starts) {
                EXPECT_TRUE(v.point);
                EXPECT_EQ(v.state.scores[index(s.starter)], options.target);
            }
            EXPECT_FALSE(physics::validate_layout(t, p, physics::balls_at_rest(v.state.positions)));
            over = v.game_over;
            s = v.state;
        }
        EXPECT_TRUE(over) << "seed " << seed;
        std::printf("three-cushion game seed %llu: %d strokes, %d-%d in %d-%d innings\n",
                    static_cast<unsigned long long>(seed), strokes, s.scores[0], s.scores[1],
                    s.innings[0], s.innings[1]);
    }
}

}  // namespace
}  // namespace rules
