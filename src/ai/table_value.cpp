#include "ai/internal/table_value.hpp"

#include <algorithm>
#include <array>

namespace ai {

double ball_chance_anywhere(const Position& base, const rules::GameState& s, int ball,
                            double sigma_deg) {
    const double R = base.params.ball_radius;
    double best = 0.0;
    for (int pocket = 0; pocket < 6; ++pocket) {
        std::optional<Aim> path = object_path(base.table, R, ball, pocket, s.positions);
        if (!path) continue;
        for (double turn : {0.0, 0.35, -0.35}) {
            const physics::Vec2 back{-path->object_dir.x, -path->object_dir.y};
            const physics::Vec2 dir{back.x * std::cos(turn) - back.y * std::sin(turn),
                                    back.x * std::sin(turn) + back.y * std::cos(turn)};
            const physics::Vec2 cue = path->ghost + 0.3 * dir;
            if (!base.table.on_surface(cue, R)) continue;
            bool free = true;
            for (const auto& [id, p] : s.positions)
                if (id != 0 && physics::norm(p - cue) < 2.0 * R + 1e-6) free = false;
            if (!free) continue;
            if (std::optional<Aim> a = direct_aim(base.table, R, cue, ball, pocket, s.positions))
                best = std::max(best, aim_chance(*a, R, sigma_deg));
            break;
        }
    }
    return best;
}

namespace {

// Kitchen spots tried for a ball in hand in the kitchen (fractions of the kitchen's length and
// of the width).
constexpr std::array<double, 3> kitchen_x{0.35, 0.65, 0.92};
constexpr std::array<double, 5> kitchen_y{0.12, 0.3, 0.5, 0.7, 0.88};

// The best pot with the cue ball free to go anywhere (`ball_chance_anywhere` of the best ball).
double best_in_hand_anywhere(const Position& base, const rules::GameState& s, double sigma_deg) {
    double best = 0.0;
    for (int ball : target_balls(base.ruleset, s))
        best = std::max(best, ball_chance_anywhere(base, s, ball, sigma_deg));
    return best;
}

}  // namespace

std::optional<BestAim> best_aim(const Position& base, const rules::GameState& s, physics::Vec2 cue,
                                double sigma_deg) {
    const double R = base.params.ball_radius;
    std::optional<BestAim> best;
    for (int ball : target_balls(base.ruleset, s))
        for (int pocket = 0; pocket < 6; ++pocket)
            if (std::optional<Aim> a = direct_aim(base.table, R, cue, ball, pocket, s.positions)) {
                const double q = aim_chance(*a, R, sigma_deg);
                if (!best || q > best->chance) best = BestAim{*a, q};
            }
    return best;
}

double best_shot_chance(const Position& base, const rules::GameState& s, double sigma_deg) {
    if (s.cue_ball == rules::CueBall::in_hand) return best_in_hand_anywhere(base, s, sigma_deg);
    if (s.cue_ball == rules::CueBall::in_hand_kitchen) {
        const double R = base.params.ball_radius;
        const double x_max = base.ruleset.table.head_string_x() - R;
        double best = 0.0;
        for (double fx : kitchen_x)
            for (double fy : kitchen_y) {
                const physics::Vec2 cue{R + fx * (x_max - R),
                                        R + fy * (base.table.width() - 2.0 * R)};
                if (std::optional<BestAim> b = best_aim(base, s, cue, sigma_deg))
                    best = std::max(best, b->chance);
            }
        return best;
    }
    auto cue = s.positions.find(0);
    if (cue == s.positions.end()) return 0.0;
    std::optional<BestAim> b = best_aim(base, s, cue->second, sigma_deg);
    return b ? b->chance : 0.0;
}

std::vector<int> balls_to_clear(const rules::Ruleset& rules, const rules::GameState& s) {
    if (rules.game == rules::Game::nine_ball) return {s.on_table.begin(), s.on_table.end()};
    std::vector<int> out;
    const std::optional<rules::Group> mine = s.group(s.shooter);
    if (!mine) return out;
    for (int ball : s.on_table)
        if (ball == 8 || rules::group_of(ball) == *mine) out.push_back(ball);
    return out;
}

bool near_rack_end(const rules::Ruleset& rules, const rules::GameState& s) {
    if (rules.game == rules::Game::nine_ball) return s.on_table.size() <= 4;
    return s.group_a && balls_to_clear(rules, s).size() <= 3;
}

int stuck_balls(const Position& base, const rules::GameState& s) {
    const double R = base.params.ball_radius;
    int stuck = 0;
    for (int ball : balls_to_clear(base.ruleset, s)) {
        bool open = false;
        for (int pocket = 0; pocket < 6 && !open; ++pocket)
            open = object_path(base.table, R, ball, pocket, s.positions).has_value();
        if (!open) ++stuck;
    }
    return stuck;
}

double stuck_penalty(const Position& base, const rules::GameState& s, double stuck_cost) {
    if (stuck_cost == 0.0) return 0.0;
    return stuck_cost * static_cast<double>(stuck_balls(base, s));
}

double position_value(const Position& base, const rules::GameState& s, double sigma_deg,
                      double stuck_cost) {
    return table_value(best_shot_chance(base, s, sigma_deg)) - stuck_penalty(base, s, stuck_cost);
}

double option_value(const Position& base, const rules::GameState& first, rules::ChoiceOption option,
                    rules::Player chooser, double sigma_deg, double stuck_cost) {
    using rules::ChoiceOption;
    constexpr double breaking = 0.55;  // the breaker's edge
    rules::GameState s = first;
    switch (option) {
        case ChoiceOption::rerack_and_break:
        case ChoiceOption::rebreak:
            return breaking;
        case ChoiceOption::rerack_offender_breaks:
            return 1.0 - breaking;
        case ChoiceOption::shoot:
            s.shooter = chooser;
            break;
        case ChoiceOption::pass_back:
            s.shooter = rules::other(chooser);
            break;
        case ChoiceOption::kitchen_ball_in_hand:
            s.shooter = chooser;
            s.cue_ball = rules::CueBall::in_hand_kitchen;
            s.positions.erase(0);
            break;
        case ChoiceOption::accept_table:
        case ChoiceOption::spot_8_and_continue:
        case ChoiceOption::spot_8_with_kitchen_ball_in_hand:
            break;
    }
    const double v = position_value(base, s, sigma_deg, stuck_cost);
    return s.shooter == chooser ? v : 1.0 - v;
}

double verdict_value(const Position& base, const rules::GameState& before, const rules::Verdict& v,
                     double sigma_deg, double stuck_cost) {
    const rules::Player me = before.shooter;
    if (v.game_over) return v.winner == me ? 1.0 : 0.0;
    if (v.choice) {
        double best = 0.0;
        for (rules::ChoiceOption o : v.choice->options)
            best =
                std::max(best, option_value(base, v.state, o, v.choice->by, sigma_deg, stuck_cost));
        return v.choice->by == me ? best : 1.0 - best;
    }
    const double value = position_value(base, v.state, sigma_deg, stuck_cost);
    if (v.next_shooter != me) return 1.0 - value;
    return staying_value(before, v.state, value);
}

double staying_value(const rules::GameState& before, const rules::GameState& after, double value) {
    const std::size_t down =
        before.on_table.size() - std::min(before.on_table.size(), after.on_table.size());
    return std::min(1.0,
                    value + progress_bonus * static_cast<double>(std::min<std::size_t>(down, 2)));
}

}  // namespace ai
