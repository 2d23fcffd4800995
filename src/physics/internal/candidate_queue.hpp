// The event loop's candidate queue: each ball's own next event and every pair's next contact,
// and per ball the first of those, so that the next event of the shot is a scan of one entry per
// ball and an event re-predicts only the balls it changed. Private to physics.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "physics/internal/private.hpp"

namespace physics {

/// What a predicted event is about. The order is the tie order of simultaneous events.
enum class CandidateKind : int { ball_ball = 0, line = 1, nose = 2, drop = 3, transition = 4 };

/// A predicted event: when, what, which ball (a) and which second ball or geometry (b).
struct Candidate {
    double time = std::numeric_limits<double>::infinity();
    CandidateKind kind = CandidateKind::transition;
    int a = -1;  ///< ball index
    int b = -1;  ///< second ball index, or geometry index
    bool pushing = false;

    /// Total order: time, then kind, then ball and geometry indices (determinism). NaN times
    /// compare as neither before nor after, as with std::tie(time, kind, a, b) < ….
    bool before(const Candidate& o) const {
        if (time < o.time) return true;
        if (!(time == o.time)) return false;
        if (kind != o.kind) return kind < o.kind;
        if (a != o.a) return a < o.a;
        return b < o.b;
    }
};

/// The candidates of up to kMaxBalls balls. A ball's candidates are replaced as a whole: clear
/// it, set its own candidate and its pairs, then refresh it (see Simulation::predict_for).
class CandidateQueue {
  public:
    static constexpr std::size_t kMaxBalls = 22;  ///< a snooker set; the bit sets are 32 bits

    explicit CandidateQueue(std::size_t balls);

    /// Whether ball i takes part (not pocketed), and whether it is still: velocity and
    /// acceleration exactly 0 at a finite position. Two still balls have no contact: their Δv
    /// and Δa are ±0, so the contact quartic is a constant, which never crosses.
    void set_ball(std::size_t i, bool active, bool still);
    bool active(std::size_t i) const { return ((active_ >> i) & 1u) != 0; }
    /// The balls (a bit each) whose pair with ball i is worth predicting: the other active
    /// balls not in `later`, less the still ones where ball i is still.
    std::uint32_t partners(std::size_t i, std::uint32_t later) const;

    /// Forgets ball i's own candidate and its pairs, before they are predicted again.
    void clear(std::size_t i);
    void set_own(std::size_t i, const Candidate& c) { own_[i] = c; }
    const Candidate& own(std::size_t i) const { return own_[i]; }
    /// Pair (i, j)'s next contact, at `time` (finite).
    void set_pair(std::size_t i, std::size_t j, double time, bool pushing);
    /// Brings the per-ball firsts up to date after ball i's candidates were set: ball i's
    /// afresh; another ball's only where its pair with i changed its first.
    void refresh(std::size_t i);

    /// The first of all candidates in the total order (time ∞ if there is none).
    Candidate earliest() const;

  private:
    using PairTable = std::array<std::array<double, kMaxBalls>, kMaxBalls>;
    static constexpr PairTable all_pairs(double v);

    void update_first(std::size_t k);
    void set_first_with(std::size_t k, std::size_t other);
    Candidate pair(std::size_t i, std::size_t j) const;

    std::size_t n_;
    std::uint32_t active_ = 0;  ///< a bit per ball that is not pocketed
    std::uint32_t still_ = 0;   ///< a bit per still ball (see set_ball)
    std::array<Candidate, kMaxBalls> own_{};
    /// Per ball k, the first of own_[k] and every pair of k.
    std::array<Candidate, kMaxBalls> first_{};
    const Candidate none_{};  ///< no candidate (time ∞): where earliest starts
    /// Per ball k, the other ball of first_[k] where that is a pair of k, else k.
    std::array<std::size_t, kMaxBalls> first_with_{};
    /// Per ball i, a bit for each other ball k whose first is its pair with i.
    std::array<std::uint32_t, kMaxBalls> firsts_on_{};
    /// Per pair, both ways round (a ball's pairs are one row): the predicted contact time (∞:
    /// none, and always on the diagonal) and whether it is a push.
    PairTable pair_time_;
    std::array<std::array<bool, kMaxBalls>, kMaxBalls> pair_pushing_{};
    /// Per ball, a bit for each other ball it has a predicted contact with (pair_time_ < ∞).
    std::array<std::uint32_t, kMaxBalls> paired_{};
};

// The queue is touched a few times per ball per event: its functions are defined here, inline.

constexpr CandidateQueue::PairTable CandidateQueue::all_pairs(double v) {
    PairTable m{};
    for (auto& row : m) row.fill(v);
    return m;
}

inline CandidateQueue::CandidateQueue(std::size_t balls)
    : n_(balls), pair_time_(all_pairs(std::numeric_limits<double>::infinity())) {
    for (std::size_t k = 0; k < kMaxBalls; ++k) first_with_[k] = k;
}

inline void CandidateQueue::set_ball(std::size_t i, bool active, bool still) {
    const std::uint32_t bit = 1u << i;
    active_ = active ? active_ | bit : active_ & ~bit;
    still_ = still ? still_ | bit : still_ & ~bit;
}

inline std::uint32_t CandidateQueue::partners(std::size_t i, std::uint32_t later) const {
    std::uint32_t others = active_ & ~later & ~(1u << i);
    if (((still_ >> i) & 1u) != 0) others &= ~still_;
    return others;
}

inline void CandidateQueue::clear(std::size_t i) {
    own_[i] = Candidate{};
    for (std::uint32_t m = paired_[i]; m != 0; m &= m - 1) {
        const auto j = static_cast<std::size_t>(std::countr_zero(m));
        pair_time_[i][j] = pair_time_[j][i] = std::numeric_limits<double>::infinity();
        paired_[j] &= ~(1u << i);
    }
    paired_[i] = 0;
}

inline void CandidateQueue::set_pair(std::size_t i, std::size_t j, double time, bool pushing) {
    pair_time_[i][j] = pair_time_[j][i] = time;
    pair_pushing_[i][j] = pair_pushing_[j][i] = pushing;
    paired_[i] |= 1u << j;
    paired_[j] |= 1u << i;
}

inline Candidate CandidateQueue::earliest() const {
    const Candidate* best = &none_;
    for (std::size_t i = 0; i < n_; ++i)
        if (first_[i].before(*best)) best = &first_[i];
    return *best;
}

inline void CandidateQueue::refresh(std::size_t i) {
    update_first(i);
    // Only the other balls whose first is a pair with i, or that have a new pair with i.
    for (std::uint32_t m = (firsts_on_[i] | paired_[i]) & ~(1u << i); m != 0; m &= m - 1) {
        const auto j = static_cast<std::size_t>(std::countr_zero(m));
        if (first_with_[j] == i) {
            update_first(j);
        } else if (pair_time_[i][j] < std::numeric_limits<double>::infinity() &&
                   pair_time_[i][j] <= first_[j].time) {
            const Candidate c = pair(i, j);  // (a tie is settled by before)
            if (c.before(first_[j])) {
                first_[j] = c;
                set_first_with(j, i);
            }
        }
    }
}

/// Sets first_[k] to the first of ball k's own candidate and its pairs. Pairs of k of equal
/// time are ordered by the other ball's index, so a strict < in increasing j finds the first
/// in the total order; at a tie with the own candidate the pair wins (ball_ball is the first
/// kind). NaN times never win, as with before().
inline void CandidateQueue::update_first(std::size_t k) {
    const std::array<double, kMaxBalls>& row = pair_time_[k];
    double t = std::numeric_limits<double>::infinity();
    std::size_t best = k;
    for (std::uint32_t m = paired_[k]; m != 0; m &= m - 1) {
        const auto j = static_cast<std::size_t>(std::countr_zero(m));
        if (row[j] < t) {
            t = row[j];
            best = j;
        }
    }
    if (best == k || !(t <= own_[k].time)) {
        first_[k] = own_[k];
        set_first_with(k, k);
    } else {
        first_[k] = pair(k, best);
        set_first_with(k, best);
    }
}

inline void CandidateQueue::set_first_with(std::size_t k, std::size_t other) {
    const std::size_t was = first_with_[k];
    if (was != k) firsts_on_[was] &= ~(1u << k);
    if (other != k) firsts_on_[other] |= 1u << k;
    first_with_[k] = other;
}

inline Candidate CandidateQueue::pair(std::size_t i, std::size_t j) const {
    const std::size_t lo = i < j ? i : j, hi = i < j ? j : i;
    return Candidate{pair_time_[i][j], CandidateKind::ball_ball, static_cast<int>(lo),
                     static_cast<int>(hi), pair_pushing_[i][j]};
}

}  // namespace physics
