// Choosing the candidates for the next round (selection.hpp), and the leave it keys on: the ball
// of the next pot that a noiseless stroke leaves (Evaluator::nominal with_leave).
#include "ai/internal/selection.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "ai/internal/candidates.hpp"
#include "ai/internal/evaluate.hpp"
#include "ai/internal/level.hpp"
#include "ai_support.hpp"

namespace {

using physics::Vec2;
using rules::Game;

std::vector<ai::Score> scores(const std::vector<double>& values, const std::vector<int>& leaves) {
    std::vector<ai::Score> out;
    for (std::size_t i = 0; i < values.size(); ++i) {
        ai::Score s;
        s.value = values[i];
        s.leave = leaves[i];
        out.push_back(s);
    }
    return out;
}

const std::vector<std::size_t> all{0, 1, 2, 3, 4, 5};

TEST(Selection, BestOfTakesTheBestInOrderAndTiesByIndex) {
    const auto s = scores({0.5, 0.9, 0.7, 0.9, 0.1, 0.6}, {1, 1, 1, 1, 1, 1});
    EXPECT_EQ(ai::best_of(s, all, 3), (std::vector<std::size_t>{1, 3, 2}));
    EXPECT_EQ(ai::best_of(s, {4, 0}, 5), (std::vector<std::size_t>{0, 4}));
}

TEST(Selection, DistinctLeavesGetTheirBestIn) {
    // Three strokes leave ball 2 next, one leaves nothing (a miss, −1), one ball 5, one ball 7.
    const auto s = scores({0.9, 0.8, 0.7, 0.65, 0.6, 0.5}, {2, 2, 2, -1, 5, 7});
    // Two of three kept for distinct leaves: the best leaving 2 and the best leaving 5 (the
    // miss is no leave), then the best of the rest.
    EXPECT_EQ(ai::distinct_best_of(s, s, all, 3, 2.0 / 3.0), (std::vector<std::size_t>{0, 1, 4}));
    // All of them kept for distinct leaves: 2, 5 and 7, best first.
    EXPECT_EQ(ai::distinct_best_of(s, s, all, 3, 1.0), (std::vector<std::size_t>{0, 4, 5}));
    // None kept: the plain best.
    EXPECT_EQ(ai::distinct_best_of(s, s, all, 3, 0.0), ai::best_of(s, all, 3));
    // Fewer candidates than places: all of them, best first.
    EXPECT_EQ(ai::distinct_best_of(s, s, {5, 0}, 3, 1.0), (std::vector<std::size_t>{0, 5}));
}

TEST(Selection, LeavesAreTakenFromTheirOwnScores) {
    // Ranked by the noisy scores, keyed by the nominal ones' leaves.
    const auto noisy = scores({0.2, 0.9, 0.8}, {-1, -1, -1});
    const auto nominal = scores({0.0, 0.0, 0.0}, {4, 3, 3});
    EXPECT_EQ(ai::distinct_best_of(noisy, nominal, {0, 1, 2}, 2, 1.0),
              (std::vector<std::size_t>{1, 0}));
}

TEST(NominalLeave, IsTheBallOfTheNextPot) {
    // 9-ball: the 1 straight in front of the NE corner, the 2 in the middle of the table.
    const Vec2 pocket{2.54, 1.27};
    const Vec2 dir{0.7071067811865476, 0.7071067811865476};
    const Vec2 one = pocket - 0.4 * dir;
    const ai::Position pos =
        ai_test::position(Game::nine_ball, {1, 2, 9},
                          {{0, one - 0.4 * dir}, {1, one}, {2, {1.0, 0.4}}, {9, {0.5, 1.0}}});
    const ai::Evaluator eval(pos, 1.0, 0.21);
    std::int64_t sims = 0;
    std::vector<ai::Candidate> pots =
        ai::pot_candidates(pos, pos.state.positions.at(0), false,
                           ai::effort_for(rules::Game::nine_ball, 5), 0.21, sims);
    ASSERT_FALSE(pots.empty());
    int stayed = 0;
    for (ai::Candidate& c : pots) {
        const ai::Trial t = eval.nominal(c, true);
        // Where the 1 drops, the 2 is next (or no pot of it is on from where the cue ball stops).
        EXPECT_TRUE(t.leave == -1 || (t.success && t.leave == 2)) << t.leave;
        stayed += t.leave == 2 ? 1 : 0;
        EXPECT_EQ(eval.nominal(c).leave, -1);  // not asked for
    }
    EXPECT_GT(stayed, 0);
}

}  // namespace
