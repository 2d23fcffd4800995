// Choosing the few candidates that go on to the next, costlier round of the search (planner.cpp):
// the best by score, or the best with room kept for strokes that leave other balls next.
#pragma once

#include <cstddef>
#include <vector>

#include "ai/internal/evaluate.hpp"
#include "ai/internal/private.hpp"

namespace ai {

/// The indices of the `n` best of `scores` among `which`, best first (ties: the earlier index).
std::vector<std::size_t> best_of(const std::vector<Score>& scores, std::vector<std::size_t> which,
                                 std::size_t n);

/// The same `n` indices, best first, except that up to `share` × n of them go first to the best
/// of each distinct leave (`leaves[i].leave`: the ball of the next pot the noiseless stroke
/// leaves; none, −1, is not a leave), in order of score. The search's scores favour the stroke
/// that leaves the easiest ball next; this keeps strokes that leave another ball in the running
/// for the rounds that look further ahead (the second ply), where the easiest ball next may turn
/// out a dead end.
std::vector<std::size_t> distinct_best_of(const std::vector<Score>& scores,
                                          const std::vector<Score>& leaves,
                                          std::vector<std::size_t> which, std::size_t n,
                                          double share);

}  // namespace ai
