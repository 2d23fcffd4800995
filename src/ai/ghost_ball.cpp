#include "ai/internal/ghost_ball.hpp"

#include <algorithm>
#include <cmath>

#include "game/stroke_noise.hpp"
#include "physics/cue_strike.hpp"

namespace ai {

namespace {

using physics::Vec2;

constexpr double max_cut_deg = 80.0;
constexpr double max_combination_cut_deg = 45.0;  // a combination's cut of its second ball
constexpr double clearance_slack = 1e-4;          // (unit: m)

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 ab = b - a;
    const double len2 = physics::norm2(ab);
    double t = len2 > 0.0 ? physics::dot(p - a, ab) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return physics::norm(p - (a + t * ab));
}

Vec2 unit(Vec2 v) {
    const double n = physics::norm(v);
    return n > 0.0 ? (1.0 / n) * v : Vec2{1.0, 0.0};
}

bool is_side(const physics::Pocket& p) {
    return p.id == static_cast<int>(physics::PocketId::S) ||
           p.id == static_cast<int>(physics::PocketId::N);
}

// The point the object ball's centre is sent to: a little behind the mouth, on the pocket's axis.
Vec2 aim_point(const physics::Pocket& p, double radius) {
    return p.drop_point + (is_side(p) ? 0.5 : 0.8) * radius * p.inward;
}

// Half-width of the pocket seen along `dir` (unit: m): the mouth foreshortened by the approach
// angle, less most of a ball radius; side pockets refuse steep approaches sooner.
double pocket_half_width(const physics::Table& table, const physics::Pocket& p, Vec2 dir,
                         double radius) {
    const double c = physics::dot(dir, p.inward);
    const double mouth = is_side(p) ? table.spec.side_mouth : table.spec.corner_mouth;
    const double limit = is_side(p) ? std::cos(55.0 * deg) : std::cos(62.0 * deg);
    if (c < limit) return 0.0;
    const double look = is_side(p) ? c * std::sqrt(c) : c;
    return std::max(0.0, 0.5 * mouth * look - 0.45 * radius);
}

}  // namespace

bool path_clear(Vec2 a, Vec2 b, const std::map<int, Vec2>& balls, int skip1, int skip2,
                double radius) {
    for (const auto& [id, p] : balls) {
        if (id == skip1 || id == skip2) continue;
        if (distance_to_segment(p, a, b) < 2.0 * radius - clearance_slack) return false;
    }
    return true;
}

std::optional<Aim> object_path(const physics::Table& table, double radius, int ball, int pocket,
                               const std::map<int, Vec2>& balls) {
    auto it = balls.find(ball);
    if (it == balls.end()) return std::nullopt;
    const physics::Pocket& pk = table.pockets[static_cast<std::size_t>(pocket)];
    Aim a;
    a.ball = ball;
    a.pocket = pocket;
    a.aim_point = aim_point(pk, radius);
    const Vec2 obj = it->second;
    a.object_distance = physics::norm(a.aim_point - obj);
    a.object_dir = unit(a.aim_point - obj);
    const double half = pocket_half_width(table, pk, a.object_dir, radius);
    if (half <= 0.0) return std::nullopt;
    a.tolerance = std::atan2(half, std::max(a.object_distance, radius));
    a.ghost = obj - 2.0 * radius * a.object_dir;
    if (!table.on_surface(a.ghost, radius * 0.999)) return std::nullopt;
    if (!path_clear(obj, a.aim_point, balls, ball, 0, radius)) return std::nullopt;
    for (const auto& [id, p] : balls)  // the ghost must be free for the cue ball
        if (id != ball && physics::norm(p - a.ghost) < 2.0 * radius - clearance_slack)
            return std::nullopt;
    return a;
}

std::optional<Aim> direct_aim(const physics::Table& table, double radius, Vec2 cue, int ball,
                              int pocket, const std::map<int, Vec2>& balls) {
    std::optional<Aim> a = object_path(table, radius, ball, pocket, balls);
    if (!a) return std::nullopt;
    const Vec2 to_ghost = a->ghost - cue;
    a->cue_distance = physics::norm(to_ghost);
    if (a->cue_distance < 1e-6) return std::nullopt;
    const Vec2 c = (1.0 / a->cue_distance) * to_ghost;
    const double cos_cut = std::clamp(physics::dot(c, a->object_dir), -1.0, 1.0);
    a->cut_deg = std::acos(cos_cut) / deg;
    if (a->cut_deg > max_cut_deg) return std::nullopt;
    a->heading_deg = std::atan2(c.y, c.x) / deg;
    if (!path_clear(cue, a->ghost, balls, ball, 0, radius)) return std::nullopt;
    return a;
}

std::optional<Combination> combination_path(const physics::Table& table, double radius, int first,
                                            int second, int pocket,
                                            const std::map<int, Vec2>& balls) {
    auto it = balls.find(first);
    if (first == second || it == balls.end()) return std::nullopt;
    std::optional<Aim> to_pocket = object_path(table, radius, second, pocket, balls);
    if (!to_pocket) return std::nullopt;
    const Vec2 start = it->second;
    Aim f;
    f.ball = first;
    f.pocket = pocket;
    f.aim_point = to_pocket->ghost;
    f.object_distance = physics::norm(f.aim_point - start);
    if (f.object_distance < 1e-6) return std::nullopt;
    f.object_dir = unit(f.aim_point - start);
    const double cos_second =
        std::clamp(physics::dot(f.object_dir, to_pocket->object_dir), -1.0, 1.0);
    const double cut_second_deg = std::acos(cos_second) / deg;
    if (cut_second_deg > max_combination_cut_deg) return std::nullopt;
    if (!path_clear(start, f.aim_point, balls, first, second, radius)) return std::nullopt;
    // An error ε of the first ball's direction turns the second by about ε·(d / (2R cos φ) + 1).
    const double gain = f.object_distance / (2.0 * radius * cos_second) + 1.0;
    f.tolerance = to_pocket->tolerance / gain;
    f.ghost = start - 2.0 * radius * f.object_dir;
    if (!table.on_surface(f.ghost, radius * 0.999)) return std::nullopt;
    for (const auto& [id, p] : balls)
        if (id != first && physics::norm(p - f.ghost) < 2.0 * radius - clearance_slack)
            return std::nullopt;
    Aim s = *to_pocket;
    s.cut_deg = cut_second_deg;
    return Combination{f, s};
}

std::optional<Combination> combination_aim(const physics::Table& table, double radius, Vec2 cue,
                                           int first, int second, int pocket,
                                           const std::map<int, Vec2>& balls) {
    constexpr double max_first_cut_deg = 70.0;  // at the first ball
    std::optional<Combination> combination =
        combination_path(table, radius, first, second, pocket, balls);
    if (!combination) return std::nullopt;
    Aim& f = combination->first;
    const Vec2 to_ghost = f.ghost - cue;
    f.cue_distance = physics::norm(to_ghost);
    if (f.cue_distance < 1e-6) return std::nullopt;
    const Vec2 c = (1.0 / f.cue_distance) * to_ghost;
    f.cut_deg = std::acos(std::clamp(physics::dot(c, f.object_dir), -1.0, 1.0)) / deg;
    if (f.cut_deg > max_first_cut_deg) return std::nullopt;
    f.heading_deg = std::atan2(c.y, c.x) / deg;
    if (!path_clear(cue, f.ghost, balls, first, 0, radius)) return std::nullopt;
    return combination;
}

double combination_chance(const Combination& c, double radius, double sigma_deg) {
    // The second contact throws the second ball by a little that no refinement corrects.
    const double thin = 1.0 - 0.25 * std::pow(c.second.cut_deg / max_combination_cut_deg, 2.0);
    return aim_chance(c.first, radius, sigma_deg) * thin;
}

double heading_sigma_deg(const physics::Params& params) {
    const game::StrokeNoise sigma;
    const double squirt_deg = physics::squirt_per_side_offset(params) * sigma.offset / deg;
    return std::hypot(sigma.heading_deg, squirt_deg);
}

double aim_chance(const Aim& a, double radius, double sigma_deg) {
    const double cos_cut = std::max(std::cos(a.cut_deg * deg), 0.1);
    const double gain = a.cue_distance / (2.0 * radius * cos_cut) + 1.0;
    const double sigma = std::max(sigma_deg, min_model_sigma_deg) * deg * gain;
    // Thin cuts throw more and vary more: a mild extra penalty.
    const double thin = 1.0 - 0.25 * std::pow(a.cut_deg / max_cut_deg, 2.0);
    return std::erf(a.tolerance / (std::sqrt(2.0) * sigma)) * thin;
}

}  // namespace ai
