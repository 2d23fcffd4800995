// The event loop's candidate queue (src/physics/candidate_queue.hpp): the earliest candidate in
// the total order, kept up to date as balls are re-predicted one at a time.
#include "physics/internal/candidate_queue.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace physics {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Candidate own(std::size_t i, double t, CandidateKind kind = CandidateKind::transition, int g = -1) {
    return Candidate{t, kind, static_cast<int>(i), g, false};
}

/// A queue of n active, moving balls, each with its own candidate at `own_times[i]`.
CandidateQueue with_own(std::initializer_list<double> own_times) {
    CandidateQueue q(own_times.size());
    std::size_t i = 0;
    for (double t : own_times) {
        q.set_ball(i, true, false);
        q.clear(i);
        q.set_own(i, own(i, t));
        q.refresh(i);
        ++i;
    }
    return q;
}

void expect_candidate(const Candidate& c, double t, CandidateKind kind, int a, int b) {
    EXPECT_EQ(c.time, t);
    EXPECT_EQ(c.kind, kind);
    EXPECT_EQ(c.a, a);
    EXPECT_EQ(c.b, b);
}

TEST(CandidateQueue, EmptyQueueHasNoEvent) {
    const CandidateQueue q(4);
    EXPECT_TRUE(std::isinf(q.earliest().time));
}

TEST(CandidateQueue, EarliestOwnCandidate) {
    const CandidateQueue q = with_own({0.5, 0.2, 0.9});
    expect_candidate(q.earliest(), 0.2, CandidateKind::transition, 1, -1);
}

TEST(CandidateQueue, TiesFollowKindThenIndices) {
    CandidateQueue q = with_own({0.3, 0.3, 0.3});
    // A cushion of ball 2 at the same time comes before the transitions (kind order)...
    q.clear(2);
    q.set_own(2, own(2, 0.3, CandidateKind::line, 5));
    q.refresh(2);
    expect_candidate(q.earliest(), 0.3, CandidateKind::line, 2, 5);
    // ...and a ball–ball contact at that time before the cushion.
    q.clear(1);
    q.set_own(1, own(1, 0.3));
    q.set_pair(1, 0, 0.3, false);
    q.refresh(1);
    expect_candidate(q.earliest(), 0.3, CandidateKind::ball_ball, 0, 1);
}

TEST(CandidateQueue, PairIsOrderedLowIndexFirstAndKeepsPushing) {
    CandidateQueue q = with_own({1.0, 1.0, 1.0});
    q.clear(2);
    q.set_own(2, own(2, 1.0));
    q.set_pair(2, 0, 0.25, true);
    q.refresh(2);
    const Candidate c = q.earliest();
    expect_candidate(c, 0.25, CandidateKind::ball_ball, 0, 2);
    EXPECT_TRUE(c.pushing);
}

TEST(CandidateQueue, ReplacingABallDropsItsOldPairs) {
    CandidateQueue q = with_own({1.0, 1.0, 1.0});
    q.clear(1);
    q.set_own(1, own(1, 1.0));
    q.set_pair(1, 2, 0.1, false);
    q.refresh(1);
    expect_candidate(q.earliest(), 0.1, CandidateKind::ball_ball, 1, 2);
    // Ball 2 is re-predicted (its pair with 1 gone): ball 1's first must fall back to its own.
    q.clear(2);
    q.set_own(2, own(2, 0.7));
    q.refresh(2);
    expect_candidate(q.earliest(), 0.7, CandidateKind::transition, 2, -1);
}

TEST(CandidateQueue, ANewPairBecomesTheOtherBallsFirst) {
    CandidateQueue q = with_own({1.0, 0.8, 0.6});
    // Ball 0 gets a pair with ball 2 before ball 2's own event: both see it.
    q.clear(0);
    q.set_own(0, own(0, 1.0));
    q.set_pair(0, 2, 0.4, false);
    q.refresh(0);
    expect_candidate(q.earliest(), 0.4, CandidateKind::ball_ball, 0, 2);
    // Ball 0 re-predicted with no pair: the earliest is ball 2's own again, not the stale pair.
    q.clear(0);
    q.set_own(0, own(0, 1.0));
    q.refresh(0);
    expect_candidate(q.earliest(), 0.6, CandidateKind::transition, 2, -1);
}

TEST(CandidateQueue, PartnersSkipInactiveLaterAndTwoStillBalls) {
    CandidateQueue q(5);
    q.set_ball(0, true, true);                     // still
    q.set_ball(1, true, true);                     // still
    q.set_ball(2, true, false);                    // moving
    q.set_ball(3, false, false);                   // pocketed
    q.set_ball(4, true, false);                    // moving
    EXPECT_EQ(q.partners(0, 0), 0b10100u);         // not 1 (both still), not 3 (pocketed)
    EXPECT_EQ(q.partners(2, 0), 0b10011u);         // a moving ball pairs with still ones
    EXPECT_EQ(q.partners(2, 0b10000u), 0b00011u);  // not the balls predicted later
    EXPECT_FALSE(q.active(3));
    EXPECT_TRUE(q.active(4));
}

TEST(CandidateQueue, MatchesAFullScanUnderRandomUpdates) {
    // The queue's earliest against a brute-force scan of every own candidate and pair, over a
    // long seeded run of re-predictions (coarse times, so that ties are frequent).
    constexpr std::size_t n = 7;
    std::array<Candidate, n> owns{};
    std::array<std::array<double, n>, n> pairs{};
    for (auto& row : pairs) row.fill(kInf);
    CandidateQueue q(n);
    std::uint64_t state = 12345;
    auto next = [&] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return state >> 33;
    };
    for (std::size_t i = 0; i < n; ++i) q.set_ball(i, true, false);
    for (int round = 0; round < 20000; ++round) {
        const std::size_t i = next() % n;
        q.clear(i);
        for (std::size_t j = 0; j < n; ++j) pairs[i][j] = pairs[j][i] = kInf;
        owns[i] = own(i, static_cast<double>(next() % 50),
                      static_cast<CandidateKind>(1 + next() % 4), static_cast<int>(next() % 3));
        q.set_own(i, owns[i]);
        for (std::size_t j = 0; j < n; ++j) {
            if (j == i || next() % 3 != 0) continue;
            pairs[i][j] = pairs[j][i] = static_cast<double>(next() % 50);
            q.set_pair(i, j, pairs[i][j], false);
        }
        q.refresh(i);
        Candidate best{};
        for (std::size_t k = 0; k < n; ++k) {
            if (owns[k].before(best)) best = owns[k];
            for (std::size_t j = k + 1; j < n; ++j) {
                const Candidate c{pairs[k][j], CandidateKind::ball_ball, static_cast<int>(k),
                                  static_cast<int>(j), false};
                if (c.before(best)) best = c;
            }
        }
        const Candidate got = q.earliest();
        ASSERT_EQ(got.time, best.time) << "round " << round;
        ASSERT_EQ(got.kind, best.kind) << "round " << round;
        ASSERT_EQ(got.a, best.a) << "round " << round;
        ASSERT_EQ(got.b, best.b) << "round " << round;
    }
}

}  // namespace
}  // namespace physics
