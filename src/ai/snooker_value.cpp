// What a snooker table is worth to the player at it, and the balls he may play
// (snooker_search.hpp).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "ai/internal/ghost_ball.hpp"
#include "ai/internal/snooker_search.hpp"

namespace ai {

namespace {

namespace sb = physics::snooker_ball;
using physics::Vec2;

constexpr double go_on_value = 2.0;       // what a pot leaves to go on with (unit: points)
constexpr double snookered_value = -2.0;  // a snookered player's expectation (unit: points)
constexpr int pockets = 6;
constexpr double near_value = 0.5;  // a cue ball on a ball on (unit: points)
constexpr double near_reach = 1.5;  // … falling to 0 at this distance (unit: m)
constexpr double tight_gap = 0.02;  // a cue ball this close to a cushion is tight (unit: m)
constexpr double tight_cost = 0.4;  // (unit: points)
constexpr int d_value_spots = 12;   // spots of the D valued for a ball in hand

int lowest_colour(const rules::SnookerState& s) {
    for (int c = sb::yellow; c <= sb::black; ++c)
        if (s.has(c)) return c;
    return sb::black;
}

// The points a pot of `ball` scores in `s`.
int pot_points(const rules::SnookerState& s, int ball) {
    if (s.free_ball && !s.colour_on)
        return s.reds() > 0 ? 1 : physics::snooker_value(lowest_colour(s));
    return physics::snooker_value(ball);
}

// What the cue ball's lie is worth beyond the pots it has: near a ball on the player has more
// and easier strokes (safeties, position), on a cushion fewer (the cue is raised over it).
double lie_value(const SnookerPosition& pos, const rules::SnookerState& s,
                 const std::map<int, Vec2>& balls, Vec2 cue) {
    double nearest = 10.0;
    for (int ball : snooker_targets(s))
        if (balls.count(ball)) nearest = std::min(nearest, physics::norm(balls.at(ball) - cue));
    const double R = pos.params.ball_radius;
    const double L = pos.snooker.marks.length, W = pos.snooker.marks.width;
    const double rail = std::min({cue.x, cue.y, L - cue.x, W - cue.y}) - R;
    return near_value * std::max(0.0, 1.0 - nearest / near_reach) -
           (rail < tight_gap ? tight_cost : 0.0);
}

double value_from(const SnookerPosition& pos, const rules::SnookerState& s, Vec2 cue,
                  double sigma_deg) {
    const double R = pos.params.ball_radius;
    const std::map<int, Vec2> balls = object_balls(s);
    double best = 0.0;
    for (int ball : snooker_targets(s)) {
        const auto it = balls.find(ball);
        if (it == balls.end()) continue;
        for (int pocket = 0; pocket < pockets; ++pocket)
            if (std::optional<Aim> a = direct_aim(pos.table, R, cue, ball, pocket, balls))
                best = std::max(best,
                                aim_chance(*a, R, sigma_deg) * (pot_points(s, ball) + go_on_value));
    }
    if (best <= 0.0 && !ball_in_view(s, cue, R)) return snookered_value;
    return best + lie_value(pos, s, balls, cue);
}

}  // namespace

double contact_heading(Vec2 cue, Vec2 target, double f, double R) {
    const Vec2 to = target - cue;
    const double d = physics::norm(to);
    const double turn = std::asin(std::clamp(f * 2.0 * R / std::max(d, 2.0 * R), -1.0, 1.0));
    return (std::atan2(to.y, to.x) + turn) * 180.0 / std::numbers::pi;
}

bool can_meet(Vec2 cue, const std::map<int, Vec2>& balls, int target, double f, double R) {
    const Vec2 to = balls.at(target) - cue;
    const double d = physics::norm(to);
    if (d <= 2.0 * R) return true;
    const double turn = std::asin(std::clamp(f * 2.0 * R / d, -1.0, 1.0));
    const double h = std::atan2(to.y, to.x) + turn;
    const Vec2 u{std::cos(h), std::sin(h)};
    // Along u the cue ball's centre first comes within 2R of the target's at distance t.
    const double along = u.x * to.x + u.y * to.y, across = std::abs(u.x * to.y - u.y * to.x);
    const double t = along - std::sqrt(std::max(4.0 * R * R - across * across, 0.0));
    return path_clear(cue, cue + t * u, balls, target, -1, R);
}

bool ball_in_view(const rules::SnookerState& s, Vec2 cue, double R) {
    const std::map<int, Vec2> balls = object_balls(s);
    for (int ball : snooker_targets(s)) {
        if (!balls.count(ball)) continue;
        for (double f : {0.0, -0.5, 0.5, -0.85, 0.85})
            if (can_meet(cue, balls, ball, f, R)) return true;
    }
    return false;
}

bool needs_nomination(const rules::SnookerState& s) {
    return s.colour_on || s.free_ball;
}

std::vector<int> snooker_targets(const rules::SnookerState& s) {
    std::vector<int> out;
    for (int id : s.on_table) {
        const bool on = s.free_ball    ? true
                        : s.colour_on  ? physics::is_colour(id)
                        : s.reds() > 0 ? physics::is_red(id)
                                       : id == lowest_colour(s);
        if (on) out.push_back(id);
    }
    return out;
}

std::map<int, Vec2> object_balls(const rules::SnookerState& s) {
    std::map<int, Vec2> out;
    for (const auto& [id, p] : s.positions)
        if (id != sb::cue && s.has(id)) out[id] = p;
    return out;
}

std::vector<physics::BallState> snooker_layout(const rules::SnookerState& s, Vec2 cue) {
    std::vector<physics::BallState> out;
    physics::BallState c;
    c.id = sb::cue;
    c.pos = cue;
    out.push_back(c);
    for (const auto& [id, p] : object_balls(s)) {
        physics::BallState b;
        b.id = id;
        b.pos = p;
        out.push_back(b);
    }
    return out;
}

std::vector<Vec2> d_spots(const SnookerPosition& pos, const rules::SnookerState& s) {
    const physics::SnookerMarkings& m = pos.snooker.marks;
    const double R = pos.params.ball_radius;
    const std::map<int, Vec2> balls = object_balls(s);
    std::vector<Vec2> out;
    // The baulk line (the D's straight edge) and two arcs inside it, from one side to the other.
    for (double r : {0.97, 0.55}) {
        for (int i = 0; i <= 8; ++i) {
            const double a = std::numbers::pi * (0.5 + i / 8.0);
            const Vec2 p = m.d_centre() +
                           Vec2{r * m.d_radius * std::cos(a) - 1e-4, r * m.d_radius * std::sin(a)};
            if (p.x < R || !m.in_d(p)) continue;
            const bool clear = std::all_of(balls.begin(), balls.end(), [&](const auto& b) {
                return physics::norm(b.second - p) > 2.0 * R + 1e-3;
            });
            if (clear) out.push_back(p);
        }
    }
    return out;
}

double table_value(const SnookerPosition& pos, const rules::SnookerState& s, double sigma_deg) {
    if (s.cue_ball == rules::CueBall::on_table && s.positions.count(sb::cue))
        return value_from(pos, s, s.positions.at(sb::cue), sigma_deg);
    const std::vector<Vec2> spots = d_spots(pos, s);
    double best = snookered_value;
    const std::size_t step = std::max<std::size_t>(1, spots.size() / d_value_spots);
    for (std::size_t i = 0; i < spots.size(); i += step)
        best = std::max(best, value_from(pos, s, spots[i], sigma_deg));
    return best;
}

}  // namespace ai
