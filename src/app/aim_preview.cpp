#include "app/aim_preview.hpp"

#include <algorithm>
#include <cmath>

#include "physics/simulate.hpp"

namespace app {

namespace {

constexpr int path_points = 32;          // samples along each drawn path
constexpr double cue_after_time = 0.6;   // how much of the cue ball's path after contact (unit: s)
constexpr double object_max_time = 3.0;  // longest object-ball path drawn (unit: s)
constexpr double free_path_time = 4.0;   // cue ball that hits nothing: path drawn (unit: s)

glm::vec2 to_glm(physics::Vec2 p) {
    return {static_cast<float>(p.x), static_cast<float>(p.y)};
}

// Ball `id`'s centre from t0 to t1, sampled (pocketed: the path stops where it dropped).
std::vector<glm::vec2> sample_path(const physics::Shot& shot, int id, double t0, double t1) {
    std::vector<glm::vec2> out;
    if (!(t1 > t0)) return out;
    for (int k = 0; k <= path_points; ++k) {
        const double t = t0 + (t1 - t0) * k / path_points;
        const physics::BallState s = shot.state_at(id, t);
        if (s.motion == physics::Motion::pocketed) break;
        out.push_back(to_glm(s.pos));
    }
    return out;
}

// The first event after index `from` that involves `id` and changes its direction: a
// collision or a pocket.
const physics::Event* next_collision(const physics::Shot& shot, std::size_t from, int id) {
    const auto& events = shot.events();
    for (std::size_t i = from + 1; i < events.size(); ++i) {
        const physics::Event& e = events[i];
        if (!e.involves(id)) continue;
        if (e.type == physics::EventType::ball_ball || e.type == physics::EventType::cushion ||
            e.type == physics::EventType::pocket)
            return &e;
    }
    return nullptr;
}

// The pocket whose mouth the straight line from `from` along `vel` passes through (the line
// crosses the segment between the jaw noses), nearest first; empty when it points at none.
std::optional<int> pocket_in_direction(const physics::Table& table, physics::Vec2 from,
                                       physics::Vec2 vel) {
    std::optional<int> best;
    double best_t = 1e9;
    for (const physics::Pocket& p : table.pockets) {
        const physics::Vec2 m = p.mouth_b - p.mouth_a;
        const double den = vel.x * m.y - vel.y * m.x;
        if (std::fabs(den) < 1e-12) continue;
        const physics::Vec2 d = p.mouth_a - from;
        const double t = (d.x * m.y - d.y * m.x) / den;      // along vel
        const double u = (d.x * vel.y - d.y * vel.x) / den;  // along the mouth
        if (t > 0.0 && u >= 0.0 && u <= 1.0 && t < best_t) {
            best_t = t;
            best = p.id;
        }
    }
    return best;
}

// The cue ball's velocity just before the contact at `events[contact]`.
physics::Vec2 cue_incoming(const physics::Shot& shot, std::size_t contact, int cue_id) {
    const double t = shot.events()[contact].time;
    return shot.state_at(cue_id, t - 1e-9 * std::max(1.0, t)).vel;
}

PathEnd end_of(const physics::Event* next) {
    if (!next) return PathEnd::none;
    switch (next->type) {
        case physics::EventType::pocket:
            return PathEnd::pocket;
        case physics::EventType::cushion:
            return next->pocket >= 0 ? PathEnd::jaw : PathEnd::rail;
        case physics::EventType::ball_ball:
            return PathEnd::ball;
        default:
            return PathEnd::none;
    }
}

glm::vec2 unit(physics::Vec2 v) {
    const double n = physics::norm(v);
    return n > 0.0 ? to_glm((1.0 / n) * v) : glm::vec2(0.0f);
}

}  // namespace

AimPreview preview_aim(const physics::Table& table, const physics::Params& params,
                       std::span<const physics::BallState> balls, const physics::Stroke& stroke) {
    AimPreview out;
    physics::SimOptions options;
    options.max_events = 4000;  // the guide needs the first contacts only
    const physics::Shot shot = physics::simulate(table, params, balls, &stroke, options);
    const auto& events = shot.events();
    const int cue_id = stroke.ball;  // 0, or a carom player's own cue ball
    out.events = events;
    std::size_t contact = events.size();
    for (std::size_t i = 0; i < events.size(); ++i)
        if (events[i].type == physics::EventType::ball_ball && events[i].involves(cue_id)) {
            contact = i;
            break;
        }
    if (contact == events.size()) {  // hits nothing: where the cue ball goes
        out.view.cue_path = sample_path(shot, cue_id, 0.0, free_path_time);
        return out;
    }
    const physics::Event& hit = events[contact];
    const int slot = hit.ball(0) == cue_id ? 0 : 1;
    const physics::EventBall& cue = hit.balls[static_cast<std::size_t>(slot)];
    const physics::EventBall& object = hit.balls[static_cast<std::size_t>(1 - slot)];
    out.first_ball = object.id;
    out.view.cue_path = sample_path(shot, cue_id, 0.0, hit.time);
    out.view.cue_path.push_back(to_glm(cue.pos));
    out.view.ghost = to_glm(cue.pos);

    out.object_at = to_glm(object.pos);
    out.object_dir = unit(object.vel);
    out.cue_dir = unit(cue_incoming(shot, contact, cue_id));
    const physics::Event* next = next_collision(shot, contact, object.id);
    out.object_end = end_of(next);
    if (next && next->time > hit.time + object_max_time) out.object_end = PathEnd::none;
    const double object_end = next ? next->time : hit.time + object_max_time;
    out.view.object_path =
        sample_path(shot, object.id, hit.time, std::min(object_end, hit.time + object_max_time));
    if (next && next->type == physics::EventType::pocket)
        out.view.object_path.push_back(to_glm(next->balls[0].pos));
    const physics::Event* cue_next = next_collision(shot, contact, cue_id);
    const double cue_end =
        std::min(hit.time + cue_after_time, cue_next ? cue_next->time : hit.time + cue_after_time);
    out.view.cue_after = sample_path(shot, cue_id, hit.time, cue_end);

    for (std::size_t i = contact + 1; i < events.size(); ++i)
        if (events[i].type == physics::EventType::pocket && events[i].involves(object.id)) {
            out.pocket = events[i].pocket;
            out.pots = true;
            break;
        }
    if (!out.pocket) out.pocket = pocket_in_direction(table, object.pos, object.vel);
    return out;
}

}  // namespace app
