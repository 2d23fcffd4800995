#include "ai/internal/placement.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "ai/internal/ghost_ball.hpp"

namespace ai {

namespace {

using physics::Vec2;

struct Spot {
    Vec2 pos;
    double score;
    int pair;  // ball × 6 + pocket of the shot it is for; −1 for none
};

Vec2 rotate(Vec2 v, double a) {
    return {v.x * std::cos(a) - v.y * std::sin(a), v.x * std::sin(a) + v.y * std::cos(a)};
}

// The free spot `p` scored by its best direct pot: the analytic chance, a little more for a
// slight cut, which lets the cue ball go on to the next shot.
Spot scored(const Position& pos, Vec2 p, double sigma_deg) {
    const double R = pos.params.ball_radius;
    Spot spot{p, 0.0, -1};
    for (int ball : target_balls(pos.ruleset, pos.state))
        for (int pocket = 0; pocket < 6; ++pocket)
            if (std::optional<Aim> a =
                    direct_aim(pos.table, R, p, ball, pocket, pos.state.positions)) {
                const double bias = a->cut_deg > 8.0 && a->cut_deg < 35.0 ? 0.02 : 0.0;
                const double q = aim_chance(*a, R, sigma_deg) + bias;
                if (q > spot.score) {
                    spot.score = q;
                    spot.pair = ball * 6 + pocket;
                }
            }
    return spot;
}

// The free spots behind each pottable ball on the line from its pocket, and in the kitchen on a
// grid when the ball in hand is there, scored, the best first.
std::vector<Spot> ranked_spots(const Position& pos, double sigma_deg) {
    const double R = pos.params.ball_radius;
    std::vector<Spot> spots;
    const auto consider = [&](Vec2 p) {
        if (free_spot(pos, p)) spots.push_back(scored(pos, p, sigma_deg));
    };
    for (int ball : target_balls(pos.ruleset, pos.state))
        for (int pocket = 0; pocket < 6; ++pocket) {
            std::optional<Aim> path = object_path(pos.table, R, ball, pocket, pos.state.positions);
            if (!path) continue;
            const Vec2 back = -1.0 * path->object_dir;
            for (double d : {0.18, 0.32, 0.55})
                for (double turn : {0.0, 0.35, -0.35, 0.7, -0.7})
                    consider(path->ghost + d * rotate(back, turn));
        }
    if (pos.state.cue_ball == rules::CueBall::in_hand_kitchen) {
        const double W = pos.table.width();
        const double x_max = pos.ruleset.table.head_string_x() - R;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 7; ++j)
                consider({R + 0.01 + (x_max - R - 0.01) * (i + 0.5) / 4.0,
                          R + 0.01 + (W - 2.0 * R - 0.02) * (j + 0.5) / 7.0});
    }
    std::stable_sort(spots.begin(), spots.end(),
                     [](const Spot& a, const Spot& b) { return a.score > b.score; });
    return spots;
}

// Up to `count` of the ranked `spots` with a pot on: one per shot first, then the rest.
std::vector<Vec2> best_spots(const std::vector<Spot>& spots, int count) {
    std::vector<Vec2> out;
    std::set<int> pairs;
    for (const Spot& s : spots)
        if (s.score > 0.0 && static_cast<int>(out.size()) < count && pairs.insert(s.pair).second)
            out.push_back(s.pos);
    for (const Spot& s : spots)
        if (s.score > 0.0 && static_cast<int>(out.size()) < count &&
            std::find(out.begin(), out.end(), s.pos) == out.end())
            out.push_back(s.pos);
    return out;
}

// Nothing to pot: spots near a legal ball, for a safety; else the ranked `spots` in the kitchen;
// at worst the first free spot of a scan of the table.
std::vector<Vec2> safety_spots(const Position& pos, const std::vector<Spot>& spots, int count) {
    const double R = pos.params.ball_radius;
    const double L = pos.table.length(), W = pos.table.width();
    std::vector<Vec2> out;
    for (int ball : target_balls(pos.ruleset, pos.state)) {
        auto it = pos.state.positions.find(ball);
        if (it == pos.state.positions.end()) continue;
        for (int k = 0; k < 8 && static_cast<int>(out.size()) < count; ++k) {
            const Vec2 p = it->second + 0.3 * rotate({1.0, 0.0}, k * 0.7853981633974483);
            if (free_spot(pos, p)) out.push_back(p);
        }
    }
    if (pos.state.cue_ball == rules::CueBall::in_hand_kitchen && out.empty())
        for (const Spot& s : spots) {
            out.push_back(s.pos);
            if (static_cast<int>(out.size()) >= count) break;
        }
    for (double x = 2.0 * R; out.empty() && x < L; x += R)
        for (double y = 2.0 * R; y < W - R; y += R)
            if (free_spot(pos, {x, y})) {
                out.push_back({x, y});
                break;
            }
    return out;
}

}  // namespace

std::vector<Vec2> cue_spots(const Position& pos, int count, double sigma_deg) {
    const std::vector<Spot> spots = ranked_spots(pos, sigma_deg);
    std::vector<Vec2> out = best_spots(spots, count);
    if (!out.empty()) return out;
    return safety_spots(pos, spots, count);
}

std::vector<Vec2> combination_spots(const Position& pos, int count, double sigma_deg,
                                    double min_chance) {
    std::vector<Spot> best;  // the best spot of each pocket
    const std::optional<int> first = combination_first_ball(pos.ruleset, pos.state);
    if (!first || count <= 0 || pos.state.cue_ball != rules::CueBall::in_hand) return {};
    const double R = pos.params.ball_radius;
    for (int pocket = 0; pocket < 6; ++pocket) {
        std::optional<Combination> path =
            combination_path(pos.table, R, *first, 9, pocket, pos.state.positions);
        if (!path) continue;
        Spot top{{}, 0.0, pocket};
        const Vec2 back = -1.0 * path->first.object_dir;
        for (double d : {0.18, 0.32, 0.55})
            for (double turn : {0.0, 0.35, -0.35}) {
                const Vec2 p = path->first.ghost + d * rotate(back, turn);
                if (!free_spot(pos, p)) continue;
                if (std::optional<Combination> c =
                        combination_aim(pos.table, R, p, *first, 9, pocket, pos.state.positions)) {
                    const double q = combination_chance(*c, R, sigma_deg);
                    if (q > top.score) top = {p, q, pocket};
                }
            }
        if (top.score >= min_chance) best.push_back(top);
    }
    std::stable_sort(best.begin(), best.end(),
                     [](const Spot& a, const Spot& b) { return a.score > b.score; });
    std::vector<Vec2> out;
    for (const Spot& s : best)
        if (static_cast<int>(out.size()) < count) out.push_back(s.pos);
    return out;
}

}  // namespace ai
