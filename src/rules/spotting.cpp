#include "rules/spotting.hpp"

#include <cmath>
#include <optional>
#include <vector>

namespace rules {

namespace {

// Distance below 2R − this is an overlap (the same tolerance as physics::validate_layout).
constexpr double overlap_tolerance = 1e-9;  // (unit: m)

struct Blocked {
    double lo, hi;  // the x interval of the long string a ball's centre must stay out of
};

}  // namespace

physics::Vec2 spot_position(const std::map<int, physics::Vec2>& balls, const TableSize& table) {
    const physics::Vec2 spot = table.foot_spot();
    const double reach = 2.0 * table.ball_radius;
    std::vector<Blocked> blocked;
    for (const auto& [id, p] : balls) {
        double dy = p.y - spot.y;
        if (std::fabs(dy) >= reach) continue;
        double h = std::sqrt(reach * reach - dy * dy);
        blocked.push_back({p.x - h, p.x + h});
    }
    auto free = [&](double x) {
        for (const auto& [id, p] : balls) {
            double dx = p.x - x, dy = p.y - spot.y;
            if (std::sqrt(dx * dx + dy * dy) < reach - overlap_tolerance) return false;
        }
        return true;
    };

    // Behind the spot: the nearest free candidate among the spot and the ends of the intervals.
    std::optional<double> best;
    const double foot_limit = table.length - table.ball_radius;
    auto consider_behind = [&](double x) {
        if (x >= spot.x && x <= foot_limit && free(x) && (!best || x < *best)) best = x;
    };
    consider_behind(spot.x);
    for (const Blocked& b : blocked) consider_behind(b.hi);
    if (best) return {*best, spot.y};

    // In front of the spot.
    const double head_limit = table.ball_radius;
    auto consider_front = [&](double x) {
        if (x <= spot.x && x >= head_limit && free(x) && (!best || x > *best)) best = x;
    };
    for (const Blocked& b : blocked) consider_front(b.lo);
    return {best.value_or(spot.x), spot.y};
}

}  // namespace rules
