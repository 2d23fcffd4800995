// The snooker player's candidates (snooker_search.hpp): pots with position, safeties, escapes.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "ai/internal/aim.hpp"
#include "ai/internal/ghost_ball.hpp"
#include "ai/internal/snooker_search.hpp"
#include "physics/cue_strike.hpp"

namespace ai {

namespace {

using physics::Vec2;

struct Spin {
    double side, top;
};
// Stun, follow, draw, then side either way, then side with follow: the first `effort.spins`.
constexpr std::array<Spin, 7> spins{
    {{0.0, 0.0}, {0.0, 0.3}, {0.0, -0.35}, {0.25, 0.0}, {-0.25, 0.0}, {0.2, 0.25}, {-0.2, 0.25}}};
// Multiples of the speed that just gets the object ball to the pocket, most useful first.
constexpr std::array<double, 5> pot_speed_factors{1.3, 2.1, 1.0, 3.2, 1.65};
constexpr std::array<double, 3> safety_speeds{0.9, 1.8, 3.2};  // (unit: m/s)
constexpr std::array<double, 3> escape_speeds{1.8, 3.0, 4.5};  // (unit: m/s)
constexpr double min_speed = 0.25, max_speed = 9.0;            // (unit: m/s)
constexpr double arrival_speed = 0.3;  // object ball speed wanted at the pocket (unit: m/s)
constexpr int pockets = 6;

// The cue speed that gets the object ball of `aim` to its pocket with `arrival_speed`: sliding
// costs a ball about 2/7 of its speed, rolling μ_roll·g per metre (docs/physics.md).
double base_pot_speed(const physics::Params& params, const Aim& aim) {
    const double decel = params.mu_roll * params.gravity;
    const double object0 =
        1.4 * std::sqrt(arrival_speed * arrival_speed + 2.0 * decel * aim.object_distance);
    const double at_contact = object0 / (0.975 * std::max(std::cos(aim.cut_deg * deg), 0.2));
    const double cue0 = 1.2 * std::sqrt(at_contact * at_contact + 2.0 * decel * aim.cue_distance);
    return physics::cue_speed_for_ball_speed(params, cue0);
}

std::optional<Vec2> spot(bool in_hand, Vec2 cue) {
    return in_hand ? std::optional<Vec2>(cue) : std::nullopt;
}

// What a pot of `ball` is worth to rank it: the colours' values count.
double worth(const rules::SnookerState& s, int ball) {
    return s.colour_on ? physics::snooker_value(ball) : 1.0;
}

std::optional<int> nomination(const rules::SnookerState& s, int ball) {
    return needs_nomination(s) ? std::optional<int>(ball) : std::nullopt;
}

}  // namespace

std::vector<SnookerCandidate> snooker_pots(const SnookerPosition& pos, Vec2 cue, bool in_hand,
                                           const SnookerEffort& effort, double sigma_deg,
                                           std::int64_t& simulations) {
    const double R = pos.params.ball_radius;
    const rules::SnookerState& s = pos.state;
    const std::map<int, Vec2> balls = object_balls(s);
    struct Ranked {
        Aim aim;
        double chance, rank;
    };
    std::vector<Ranked> aims;
    for (int ball : snooker_targets(s))
        for (int pocket = 0; pocket < pockets; ++pocket)
            if (std::optional<Aim> a = direct_aim(pos.table, R, cue, ball, pocket, balls)) {
                const double chance = aim_chance(*a, R, sigma_deg);
                aims.push_back({*a, chance, chance * (worth(s, ball) + 2.0)});
            }
    std::stable_sort(aims.begin(), aims.end(),
                     [](const Ranked& a, const Ranked& b) { return a.rank > b.rank; });
    if (aims.size() > static_cast<std::size_t>(effort.pot_pairs))
        aims.resize(static_cast<std::size_t>(effort.pot_pairs));
    std::vector<SnookerCandidate> out;
    for (const Ranked& r : aims) {
        const double base = base_pot_speed(pos.params, r.aim);
        const Vec2 object = balls.at(r.aim.ball);
        for (int j = 0; j < std::min<int>(effort.spins, spins.size()); ++j) {
            physics::Stroke stroke;
            stroke.side = spins[static_cast<std::size_t>(j)].side;
            stroke.top = spins[static_cast<std::size_t>(j)].top;
            stroke.speed = std::clamp(base * pot_speed_factors[0], min_speed, max_speed);
            stroke.heading_deg = refine_heading(pos.table, pos.params, cue, object, r.aim, stroke,
                                                effort.refine_steps, simulations);
            for (int k = 0; k < std::min<int>(effort.speeds, pot_speed_factors.size()); ++k) {
                SnookerCandidate c;
                c.kind = Kind::pot;
                c.stroke = stroke;
                c.stroke.speed = std::clamp(base * pot_speed_factors[static_cast<std::size_t>(k)],
                                            min_speed, max_speed);
                c.cue_pos = spot(in_hand, cue);
                c.target = r.aim.ball;
                c.nominated = nomination(s, r.aim.ball);
                c.prior = r.chance;
                out.push_back(c);
            }
        }
    }
    return out;
}

std::vector<SnookerCandidate> snooker_safeties(const SnookerPosition& pos, Vec2 cue, bool in_hand,
                                               const SnookerEffort& effort) {
    const double R = pos.params.ball_radius;
    const std::map<int, Vec2> balls = object_balls(pos.state);
    std::vector<int> targets = snooker_targets(pos.state);
    const int n = std::max(effort.safety_contacts, 1);
    const auto contact = [&](int i) { return n == 1 ? 0.0 : -0.9 + 1.8 * i / (n - 1); };
    std::erase_if(targets, [&](int b) {
        if (!balls.count(b)) return true;
        for (int i = 0; i < n; ++i)
            if (can_meet(cue, balls, b, contact(i), R)) return false;
        return true;
    });
    std::stable_sort(targets.begin(), targets.end(), [&](int a, int b) {
        return physics::norm(balls.at(a) - cue) < physics::norm(balls.at(b) - cue);
    });
    if (targets.size() > static_cast<std::size_t>(effort.safety_balls))
        targets.resize(static_cast<std::size_t>(effort.safety_balls));
    std::vector<SnookerCandidate> out;
    for (int ball : targets) {
        for (int i = 0; i < n; ++i) {
            const double f = contact(i);
            if (!can_meet(cue, balls, ball, f, R)) continue;
            for (int k = 0; k < std::min<int>(effort.safety_speeds, safety_speeds.size()); ++k) {
                SnookerCandidate c;
                c.kind = Kind::safety;
                c.stroke.speed = safety_speeds[static_cast<std::size_t>(k)];
                c.stroke.heading_deg = contact_heading(cue, balls.at(ball), f, R);
                c.cue_pos = spot(in_hand, cue);
                c.target = ball;
                c.nominated = nomination(pos.state, ball);
                out.push_back(c);
            }
        }
    }
    return out;
}

std::vector<SnookerCandidate> snooker_escapes(const SnookerPosition& pos, Vec2 cue, bool in_hand,
                                              const SnookerEffort& effort) {
    (void)pos;
    std::vector<SnookerCandidate> out;
    const int n = std::max(effort.sweep_headings, 8);
    for (int i = 0; i < n; ++i)
        for (double speed : escape_speeds) {
            SnookerCandidate c;
            c.kind = Kind::kick;
            c.stroke.speed = speed;
            c.stroke.heading_deg = 360.0 * i / n;
            c.cue_pos = spot(in_hand, cue);
            out.push_back(c);
        }
    return out;
}

}  // namespace ai
