#include "rules/snooker_table.hpp"

#include <algorithm>
#include <cmath>

namespace rules {

namespace {

constexpr double kOverlapTolerance = 1e-9;  ///< as physics::validate_layout (unit: m)
constexpr double kTouchTolerance = 1e-6;    ///< resting balls touch within this (unit: m)
constexpr int kEdgeSamples = 16;            ///< per side, between the full ball and an edge

bool free_at(const Positions& pos, physics::Vec2 p, double R) {
    for (const auto& [id, q] : pos)
        if (physics::norm(q - p) < 2.0 * R - kOverlapTolerance) return false;
    return true;
}

/// The nearest free point from `from` along `dir` up to `limit` (inclusive), if any: the
/// candidates are `from` and the points just clear of each ball near the line.
std::optional<physics::Vec2> nearest_free(const Positions& pos, physics::Vec2 from,
                                          physics::Vec2 dir, double limit, double R) {
    std::vector<double> candidates{0.0};
    for (const auto& [id, q] : pos) {
        const physics::Vec2 d = q - from;
        const double along = physics::dot(d, dir), off = physics::cross(dir, d);
        if (std::fabs(off) >= 2.0 * R) continue;
        candidates.push_back(along + std::sqrt(4.0 * R * R - off * off));
    }
    std::sort(candidates.begin(), candidates.end());
    for (double t : candidates)
        if (t >= 0.0 && t <= limit && free_at(pos, from + t * dir, R)) return from + t * dir;
    return std::nullopt;
}

physics::Vec2 respot_one(int colour, const Positions& pos, const SnookerTable& table,
                         std::optional<int>& spot) {
    const double R = table.ball_radius;
    const physics::SnookerMarkings& m = table.marks;
    if (free_at(pos, m.spot(colour), R)) {
        spot = colour;
        return m.spot(colour);
    }
    for (int c = physics::snooker_ball::black; c >= physics::snooker_ball::yellow; --c) {
        if (free_at(pos, m.spot(c), R)) {
            spot = c;
            return m.spot(c);
        }
    }
    spot.reset();
    const physics::Vec2 own = m.spot(colour);
    if (auto p = nearest_free(pos, own, {1.0, 0.0}, m.length - R - own.x, R)) return *p;
    if (auto p = nearest_free(pos, own, {-1.0, 0.0}, own.x - R, R)) return *p;
    return own;  // a table full from cushion to cushion along the line: unreachable in play
}

/// The cue ball's straight path to hit `target` at angle offset `phi` from the line of
/// centres: where it meets the target's ball.
bool path_clear(const Positions& pos, physics::Vec2 c, physics::Vec2 o, double phi, int target,
                const std::set<int>& on, double R) {
    const physics::Vec2 to = o - c;
    const double d = physics::norm(to);
    const physics::Vec2 u0 = (1.0 / d) * to;
    const physics::Vec2 u{u0.x * std::cos(phi) - u0.y * std::sin(phi),
                          u0.x * std::sin(phi) + u0.y * std::cos(phi)};
    const double s = d * std::sin(phi);
    const double t = d * std::cos(phi) - std::sqrt(std::max(0.0, 4.0 * R * R - s * s));
    for (const auto& [id, b] : pos) {
        if (id == 0 || id == target || on.count(id) != 0) continue;
        const double along = std::clamp(physics::dot(b - c, u), 0.0, t);
        if (physics::norm(b - (c + along * u)) < 2.0 * R - kOverlapTolerance) return false;
    }
    return true;
}

}  // namespace

Positions last_positions(const Positions& before, std::span<const physics::Event> events) {
    Positions pos = before;
    for (const physics::Event& e : events)
        for (int k = 0; k < e.ball_count && k < 2; ++k) {
            const physics::EventBall& b = e.balls[static_cast<std::size_t>(k)];
            if (std::isfinite(b.pos.x) && std::isfinite(b.pos.y)) pos[b.id] = b.pos;
        }
    return pos;
}

std::vector<Respot> respot_colours(std::vector<int> colours, Positions& positions,
                                   const SnookerTable& table) {
    std::sort(colours.begin(), colours.end(), std::greater<>());
    std::vector<Respot> out;
    for (int c : colours) {
        positions.erase(c);
        Respot r{c, std::nullopt, {}};
        r.pos = respot_one(c, positions, table, r.spot);
        positions[c] = r.pos;
        out.push_back(r);
    }
    return out;
}

bool can_hit(const Positions& pos, int target, double side, const std::set<int>& on, double R) {
    const auto c = pos.find(0), o = pos.find(target);
    if (c == pos.end() || o == pos.end()) return false;
    const double d = physics::norm(o->second - c->second);
    if (d <= 2.0 * R + kTouchTolerance) return true;
    const double edge = std::asin(2.0 * R / d) * (1.0 - 1e-9);
    return path_clear(pos, c->second, o->second, side * edge, target, on, R);
}

bool is_snookered(const Positions& pos, const std::set<int>& on, double R) {
    for (int b : on)
        if (pos.count(b) != 0 && can_hit(pos, b, -1.0, on, R) && can_hit(pos, b, 1.0, on, R))
            return false;
    return true;
}

bool has_clear_path(const Positions& pos, const std::set<int>& on, double R) {
    for (int b : on)
        for (int k = -kEdgeSamples; k <= kEdgeSamples; ++k)
            if (pos.count(b) != 0 && can_hit(pos, b, double(k) / kEdgeSamples, on, R)) return true;
    return false;
}

std::optional<int> touching_ball(const Positions& pos, double R) {
    const auto c = pos.find(0);
    if (c == pos.end()) return std::nullopt;
    for (const auto& [id, p] : pos)
        if (id != 0 && physics::norm(p - c->second) <= 2.0 * R + kTouchTolerance) return id;
    return std::nullopt;
}

}  // namespace rules
