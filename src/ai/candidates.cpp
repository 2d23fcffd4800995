#include "ai/internal/candidates.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "ai/internal/aim.hpp"
#include "ai/internal/ghost_ball.hpp"
#include "physics/cue_strike.hpp"
#include "rules/eight_ball.hpp"

namespace ai {

namespace {

using physics::Vec2;

struct Spin {
    double side, top;
};
// Stun, follow, draw, right and left side, then side with follow or draw: the first
// `effort.spins` are tried.
constexpr std::array<Spin, 9> spins{{{0.0, 0.0},
                                     {0.0, 0.3},
                                     {0.0, -0.35},
                                     {0.25, 0.0},
                                     {-0.25, 0.0},
                                     {0.2, 0.25},
                                     {-0.2, 0.25},
                                     {0.2, -0.3},
                                     {-0.2, -0.3}}};
// Multiples of the speed that just gets the object ball to the pocket, most useful first.
constexpr std::array<double, 7> pot_speed_factors{1.3, 2.1, 1.0, 3.2, 4.6, 1.65, 2.6};
constexpr std::array<double, 5> safety_speeds{0.55, 1.0, 1.7, 2.6, 4.0};  // (unit: m/s)
constexpr std::array<double, 2> kick_speeds{1.6, 3.2};                    // (unit: m/s)
constexpr double min_speed = 0.25, max_speed = 8.0;                       // (unit: m/s)
constexpr double max_variant_offset = 0.44;  // a variant's tip offset stays this far from centre:
                                             // 3σ inside the miscue limit (unit: R)
constexpr double roll_decel = 0.0981;        // μ_roll·g of the default parameters (unit: m/s²)
constexpr double arrival_speed = 0.35;       // object ball speed wanted at the pocket (unit: m/s)

// The cue speed that gets the object ball of `aim` to its pocket with `arrival_speed`: sliding
// costs a ball about 2/7 of its speed, rolling μ_roll·g per metre (docs/physics.md).
double base_pot_speed(const physics::Params& params, const Aim& aim) {
    const double object0 =
        1.4 * std::sqrt(arrival_speed * arrival_speed + 2.0 * roll_decel * aim.object_distance);
    const double cue_at_contact = object0 / (0.975 * std::max(std::cos(aim.cut_deg * deg), 0.2));
    const double cue0 =
        1.2 * std::sqrt(cue_at_contact * cue_at_contact + 2.0 * roll_decel * aim.cue_distance);
    return physics::cue_speed_for_ball_speed(params, cue0);
}

// The cue speed for the combination `c`: the second ball gets to the pocket with
// `arrival_speed`, each ball losing to the slide and the roll as in `base_pot_speed`.
double base_combination_speed(const physics::Params& params, const Combination& c) {
    const auto launch = [](double arrival, double distance) {
        return 1.4 * std::sqrt(arrival * arrival + 2.0 * roll_decel * distance);
    };
    const auto struck = [](double leaving, double cut_deg) {
        return leaving / (0.975 * std::max(std::cos(cut_deg * deg), 0.2));
    };
    const double second0 = launch(arrival_speed, c.second.object_distance);
    const double first0 = launch(struck(second0, c.second.cut_deg), c.first.object_distance);
    const double cue_at_contact = struck(first0, c.first.cut_deg);
    const double cue0 =
        1.2 * std::sqrt(cue_at_contact * cue_at_contact + 2.0 * roll_decel * c.first.cue_distance);
    return physics::cue_speed_for_ball_speed(params, cue0);
}

// Raises the cue of the pot `stroke` (its heading refined on a level cue) so that a side-offset
// error's swerve cancels its squirt, keeps the ball's speed (an elevated cue drives the ball
// into the cloth by sin ε of the impulse) and refines the heading again. Not with side spin
// meant: on a raised cue that spin curves the ball by an amount the speed's error changes.
void raise_cue(const Position& pos, Vec2 cue, Vec2 object, const Aim& aim, const Effort& effort,
               physics::Stroke& stroke, std::int64_t& simulations) {
    if (effort.max_raise_deg <= 0.0 || stroke.side != 0.0) return;
    const double e = compensating_elevation(pos.table, pos.params, cue, object, aim, stroke,
                                            effort.max_raise_deg, simulations);
    if (e == stroke.elevation_deg) return;
    stroke = raised_stroke(pos.table, pos.params, cue, object, aim, stroke, e, min_speed, max_speed,
                           effort.refine_steps, simulations);
}

double heading_to(Vec2 from, Vec2 to) {
    return std::atan2(to.y - from.y, to.x - from.x) / deg;
}

std::optional<Vec2> spot(bool in_hand, Vec2 cue) {
    return in_hand ? std::optional<Vec2>(cue) : std::nullopt;
}

}  // namespace

rules::Call pot_call(const Position& pos, int ball, int pocket) {
    if (pos.ruleset.game != rules::Game::eight_ball || pos.state.shot == rules::Shot::break_shot ||
        !rules::call_counts(pos.ruleset.options, pos.state))
        return rules::Call::nothing();
    return rules::Call::ball_in(ball, pocket);
}

rules::Call safety_call(const Position& pos) {
    if (pos.ruleset.game != rules::Game::eight_ball || pos.state.shot == rules::Shot::break_shot ||
        !rules::call_counts(pos.ruleset.options, pos.state))
        return rules::Call::nothing();
    return rules::Call::safety();
}

std::vector<RankedAim> ranked_aims(const Position& pos, Vec2 cue, double sigma_deg) {
    const double R = pos.params.ball_radius;
    std::vector<RankedAim> aims;
    for (int ball : target_balls(pos.ruleset, pos.state))
        for (int pocket = 0; pocket < 6; ++pocket)
            if (std::optional<Aim> a =
                    direct_aim(pos.table, R, cue, ball, pocket, pos.state.positions))
                aims.push_back({*a, aim_chance(*a, R, sigma_deg)});
    std::stable_sort(aims.begin(), aims.end(),
                     [](const RankedAim& a, const RankedAim& b) { return a.chance > b.chance; });
    return aims;
}

std::vector<Candidate> pot_strokes(const Position& pos, Vec2 cue, bool in_hand, const RankedAim& r,
                                   const Effort& effort, std::int64_t& simulations) {
    std::vector<Candidate> out;
    const Vec2 object = pos.state.positions.at(r.aim.ball);
    const double base = base_pot_speed(pos.params, r.aim);
    for (int k = 0; k < std::min<int>(effort.speeds, static_cast<int>(pot_speed_factors.size()));
         ++k)
        for (int j = 0; j < std::min<int>(effort.spins, static_cast<int>(spins.size())); ++j) {
            Candidate c;
            c.kind = Kind::pot;
            c.prior = r.chance;
            c.aim = r.aim;
            c.cue_pos = spot(in_hand, cue);
            c.call = pot_call(pos, r.aim.ball, r.aim.pocket);
            c.stroke.speed = std::clamp(base * pot_speed_factors[static_cast<std::size_t>(k)],
                                        min_speed, max_speed);
            c.stroke.side = spins[static_cast<std::size_t>(j)].side;
            c.stroke.top = spins[static_cast<std::size_t>(j)].top;
            c.stroke.heading_deg = refine_heading(pos.table, pos.params, cue, object, r.aim,
                                                  c.stroke, effort.refine_steps, simulations);
            raise_cue(pos, cue, object, r.aim, effort, c.stroke, simulations);
            out.push_back(c);
        }
    return out;
}

std::vector<Candidate> pot_candidates(const Position& pos, Vec2 cue, bool in_hand,
                                      const Effort& effort, double sigma_deg,
                                      std::int64_t& simulations) {
    std::vector<RankedAim> aims = ranked_aims(pos, cue, sigma_deg);
    if (aims.size() > static_cast<std::size_t>(effort.pot_pairs))
        aims.resize(static_cast<std::size_t>(effort.pot_pairs));
    Effort pots = effort;
    if (sigma_deg == 0.0) pots.max_raise_deg = 0.0;  // without noise a level cue is exact
    std::vector<Candidate> out;
    for (const RankedAim& r : aims) {
        std::vector<Candidate> strokes = pot_strokes(pos, cue, in_hand, r, pots, simulations);
        out.insert(out.end(), strokes.begin(), strokes.end());
    }
    return out;
}

std::vector<RankedCombination> ranked_combinations(const Position& pos, Vec2 cue,
                                                   double sigma_deg) {
    std::vector<RankedCombination> out;
    const std::optional<int> first = combination_first_ball(pos.ruleset, pos.state);
    if (!first) return out;
    const double R = pos.params.ball_radius;
    for (int pocket = 0; pocket < 6; ++pocket)
        if (std::optional<Combination> c =
                combination_aim(pos.table, R, cue, *first, 9, pocket, pos.state.positions))
            out.push_back({*c, combination_chance(*c, R, sigma_deg)});
    std::stable_sort(
        out.begin(), out.end(),
        [](const RankedCombination& a, const RankedCombination& b) { return a.chance > b.chance; });
    return out;
}

std::vector<Candidate> combination_candidates(const Position& pos, Vec2 cue, bool in_hand,
                                              const Effort& effort, double sigma_deg,
                                              std::int64_t& simulations) {
    constexpr std::array<double, 3> speed_factors{1.3, 2.1, 3.2};
    std::vector<Candidate> out;
    if (effort.combinations <= 0) return out;
    std::vector<RankedCombination> combos = ranked_combinations(pos, cue, sigma_deg);
    if (combos.size() > static_cast<std::size_t>(effort.combinations))
        combos.resize(static_cast<std::size_t>(effort.combinations));
    for (const RankedCombination& r : combos) {
        const double base = base_combination_speed(pos.params, r.combination);
        for (double factor : speed_factors)
            for (std::size_t j = 0; j < 3; ++j) {  // stun, follow, draw
                Candidate c;
                c.kind = Kind::pot;
                c.prior = r.chance;  // no `aim`: a combination is not searched around finer
                c.cue_pos = spot(in_hand, cue);
                c.call = pot_call(pos, r.combination.second.ball, r.combination.second.pocket);
                c.stroke.speed = std::clamp(base * factor, min_speed, max_speed);
                c.stroke.side = spins[j].side;
                c.stroke.top = spins[j].top;
                c.stroke.heading_deg =
                    refine_combination_heading(pos.table, pos.params, cue, pos.state.positions,
                                               r.combination, c.stroke, 2, simulations);
                out.push_back(c);
            }
    }
    return out;
}

std::vector<Candidate> pot_variants(const Position& pos, const Candidate& c, const Effort& effort,
                                    std::int64_t& simulations) {
    struct Change {
        double speed, top;  // speed × factor, top + offset
    };
    static constexpr std::array<Change, 6> changes{
        {{0.84, 0.0}, {0.92, 0.0}, {1.08, 0.0}, {1.18, 0.0}, {1.0, 0.18}, {1.0, -0.18}}};
    std::vector<Candidate> out;
    if (c.kind != Kind::pot || !c.aim) return out;
    const Vec2 cue = c.cue_pos ? *c.cue_pos : pos.state.positions.at(0);
    const Vec2 object = pos.state.positions.at(c.aim->ball);
    for (const Change& change : changes) {
        Candidate v = c;
        v.stroke.speed = std::clamp(c.stroke.speed * change.speed, min_speed, max_speed);
        v.stroke.top = c.stroke.top + change.top;
        if (std::hypot(v.stroke.side, v.stroke.top) > max_variant_offset) continue;
        if (v.stroke.speed == c.stroke.speed && v.stroke.top == c.stroke.top) continue;
        v.stroke.heading_deg =
            refine_heading(pos.table, pos.params, cue, object, *c.aim, v.stroke, 2, simulations);
        if (c.stroke.elevation_deg > 0.0)
            raise_cue(pos, cue, object, *c.aim, effort, v.stroke, simulations);
        out.push_back(v);
    }
    return out;
}

std::vector<Candidate> safety_candidates(const Position& pos, Vec2 cue, bool in_hand,
                                         const Effort& effort) {
    const double R = pos.params.ball_radius;
    std::vector<Candidate> out;
    const int n = std::max(effort.safety_contacts, 1);
    for (int ball : target_balls(pos.ruleset, pos.state)) {
        auto it = pos.state.positions.find(ball);
        if (it == pos.state.positions.end()) continue;
        const double d = physics::norm(it->second - cue);
        if (d <= 2.0 * R) continue;
        const double centre = heading_to(cue, it->second);
        for (int i = 0; i < n; ++i) {
            const double f = n == 1 ? 0.0 : -0.85 + 1.7 * i / (n - 1);
            const double turn = std::asin(std::clamp(f * 2.0 * R / d, -1.0, 1.0)) / deg;
            for (int k = 0;
                 k < std::min<int>(effort.safety_speeds, static_cast<int>(safety_speeds.size()));
                 ++k) {
                Candidate c;
                c.kind = Kind::safety;
                c.cue_pos = spot(in_hand, cue);
                c.call = safety_call(pos);
                c.stroke.speed = safety_speeds[static_cast<std::size_t>(k)];
                c.stroke.heading_deg = centre + turn;
                out.push_back(c);
            }
        }
    }
    return out;
}

std::vector<Candidate> kick_candidates(const Position& pos, Vec2 cue, bool in_hand,
                                       const Effort& effort) {
    (void)pos;
    std::vector<Candidate> out;
    const int n = std::max(effort.sweep_headings, 8);
    for (int i = 0; i < n; ++i)
        for (double speed : kick_speeds) {
            Candidate c;
            c.kind = Kind::kick;
            c.cue_pos = spot(in_hand, cue);
            c.stroke.speed = speed;
            c.stroke.heading_deg = 360.0 * i / n;
            out.push_back(c);
        }
    return out;
}

std::optional<Candidate> break_candidate(const Position& pos, const BreakSpec& spec) {
    const double R = pos.params.ball_radius;
    const double W = pos.table.width();
    // The apex ball: the object ball nearest the head cushion.
    Vec2 apex{pos.table.length() * 0.75, W / 2.0};
    double best_x = 1e9;
    for (const auto& [id, p] : pos.state.positions)
        if (id != 0 && p.x < best_x) {
            best_x = p.x;
            apex = p;
        }
    const Vec2 cue{pos.ruleset.table.head_string_x() - 2.0 * R, W / 2.0 + spec.offset};
    if (!free_spot(pos, cue)) return std::nullopt;
    const double d = physics::norm(apex - cue);
    Candidate c;
    c.kind = Kind::break_shot;
    c.cue_pos = cue;
    c.stroke.speed = spec.speed;
    c.stroke.top = -0.1;  // a touch of draw keeps the cue ball off the rails
    const double sign = spec.offset >= 0.0 ? 1.0 : -1.0;
    c.stroke.heading_deg =
        heading_to(cue, apex) + sign * std::asin(spec.contact * 2.0 * R / d) / deg;
    return c;
}

std::vector<BreakSpec> broad_breaks() {
    std::vector<BreakSpec> out;
    for (double offset : {0.0, 0.15, -0.15, 0.32, -0.32})
        for (double contact : {0.0, 0.25})
            for (double speed : {6.5, 8.0, 9.5}) out.push_back({offset, contact, speed});
    return out;
}

std::vector<Candidate> break_candidates(const Position& pos, bool tuned) {
    std::vector<Candidate> out;
    const std::vector<BreakSpec> specs =
        tuned ? std::vector<BreakSpec>(tuned_breaks.begin(), tuned_breaks.end()) : broad_breaks();
    for (const BreakSpec& spec : specs)
        if (std::optional<Candidate> c = break_candidate(pos, spec)) out.push_back(*c);
    return out;
}

std::vector<Candidate> push_out_candidates(const Position& pos, Vec2 cue) {
    (void)pos;
    std::vector<Candidate> out;
    for (int i = 0; i < 24; ++i)
        for (double speed : {0.35, 0.7}) {
            Candidate c;
            c.kind = Kind::push_out;
            c.stroke.speed = speed;
            c.stroke.heading_deg = 15.0 * i;
            (void)cue;
            out.push_back(c);
        }
    return out;
}

}  // namespace ai
