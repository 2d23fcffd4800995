#include "ai/internal/selection.hpp"

#include <algorithm>

namespace ai {

namespace {

void sort_by_score(const std::vector<Score>& scores, std::vector<std::size_t>& which) {
    std::stable_sort(which.begin(), which.end(), [&](std::size_t a, std::size_t b) {
        return scores[a].value > scores[b].value;
    });
}

}  // namespace

std::vector<std::size_t> best_of(const std::vector<Score>& scores, std::vector<std::size_t> which,
                                 std::size_t n) {
    sort_by_score(scores, which);
    if (which.size() > n) which.resize(n);
    return which;
}

std::vector<std::size_t> distinct_best_of(const std::vector<Score>& scores,
                                          const std::vector<Score>& leaves,
                                          std::vector<std::size_t> which, std::size_t n,
                                          double share) {
    sort_by_score(scores, which);
    if (which.size() <= n) return which;
    const auto reserved = static_cast<std::size_t>(share * static_cast<double>(n));
    std::vector<bool> taken(which.size(), false);
    std::vector<int> seen;
    std::size_t count = 0;
    for (std::size_t k = 0; k < which.size() && count < reserved; ++k) {
        const int leave = leaves[which[k]].leave;
        if (leave < 0 || std::find(seen.begin(), seen.end(), leave) != seen.end()) continue;
        seen.push_back(leave);
        taken[k] = true;
        ++count;
    }
    for (std::size_t k = 0; k < which.size() && count < n; ++k)
        if (!taken[k]) {
            taken[k] = true;
            ++count;
        }
    std::vector<std::size_t> out;
    out.reserve(n);
    for (std::size_t k = 0; k < which.size(); ++k)
        if (taken[k]) out.push_back(which[k]);
    return out;
}

}  // namespace ai
