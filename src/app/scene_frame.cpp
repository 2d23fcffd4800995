#include "app/scene_frame.hpp"

#include <cmath>
#include <numbers>

#include "app/aim_guide.hpp"
#include "render/pockets.hpp"

namespace app {

namespace {

// How far the cue is drawn back from the ball at a Power slider position (unit: m).
float pull_back(double power) {
    return static_cast<float>(0.015 + 0.22 * power);
}

// Balls that dropped in the last 0.6 s of the shot, falling into their pocket.
void add_dropping_balls(const Controller& c, double R, std::vector<render::BallView>& out) {
    if (!c.moving() || !c.playback().has_shot() || c.playback().time() < 0.0) return;
    const double t = c.playback().time();
    const physics::Table& table = c.session().table();
    for (const physics::Event& e : c.playback().shot().events()) {
        if (e.type != physics::EventType::pocket || e.time > t || t - e.time > render::kDropSeconds)
            continue;
        const physics::EventBall& b = e.balls[0];
        physics::BallState state;
        state.id = b.id;
        state.pos = b.pos;
        render::BallView v = render::ball_view(state, R, c.orientations().of(b.id));
        v.centre =
            render::dropping_ball_centre(table, static_cast<float>(R),
                                         {static_cast<float>(b.pos.x), static_cast<float>(b.pos.y)},
                                         static_cast<float>(t - e.time));
        out.push_back(v);
    }
}

// The stroke on show and where its cue ball lay: the match's, or the session's last shot.
std::optional<Controller::StrokeShown> last_stroke(const Controller& c) {
    if (c.snooker() || c.carom()) return c.match_stroke();
    const game::Session& s = c.session();
    if (s.history().empty()) return std::nullopt;
    const game::ShotRecord& r = s.history().back();
    const auto at = r.before.positions.find(0);
    if (at == r.before.positions.end()) return std::nullopt;
    return Controller::StrokeShown{at->second, r.stroke};
}

// The cue moving from where it was drawn back to the ball, `time` (< 0) before the strike.
render::CueView stroke_cue(const Controller::StrokeShown& s, double time) {
    render::CueView k;
    k.cue_ball = {static_cast<float>(s.cue_ball.x), static_cast<float>(s.cue_ball.y)};
    k.heading = static_cast<float>(s.stroke.heading_deg * std::numbers::pi / 180.0);
    k.elevation = static_cast<float>(s.stroke.elevation_deg * std::numbers::pi / 180.0);
    k.tip_offset = {static_cast<float>(s.stroke.side), static_cast<float>(s.stroke.top)};
    k.pull_back =
        pull_back(power_of_speed(s.stroke.speed)) * static_cast<float>(-time / stroke_lead);
    return k;
}

}  // namespace

render::FrameView SceneFrame::view(const render::Camera& camera) const {
    render::FrameView v;
    v.balls = balls;
    v.camera = camera;
    v.cue = cue;
    v.aim = show_aim ? &aim : nullptr;
    v.tray = tray;
    v.ball_in_hand = ball_in_hand;
    return v;
}

SceneFrame build_scene(const Controller& c, AimGuide aim_guide,
                       std::optional<physics::Vec2> dragged_to) {
    SceneFrame f;
    const double R = c.session().config().params.ball_radius;
    for (const physics::BallState& b : c.balls_now())
        f.balls.push_back(render::ball_view(b, R, c.orientations().of(b.id)));
    add_dropping_balls(c, R, f.balls);
    f.tray = c.tray();
    const AimPreview* preview = c.preview();
    const bool at_table = c.session().phase() == game::Phase::shoot && !c.moving();
    const auto cue = c.session().state().positions.find(c.cue_ball_id());
    if (at_table && preview && cue != c.session().state().positions.end() &&
        !c.computer_thinking()) {
        const Aim& a = c.aim();
        render::CueView k;
        k.cue_ball = {static_cast<float>(cue->second.x), static_cast<float>(cue->second.y)};
        k.heading = static_cast<float>(a.heading_deg * std::numbers::pi / 180.0);
        k.elevation = static_cast<float>(a.elevation_deg * std::numbers::pi / 180.0);
        k.pull_back = pull_back(a.power);
        k.tip_offset = {static_cast<float>(a.side), static_cast<float>(a.top)};
        f.cue = k;
        const float Rf = static_cast<float>(R);
        f.aim = guide_view(*preview, aim_guide, !c.aim_foul().empty(), Rf);
        if (!c.aim_foul().empty() && preview->first_ball)  // the ball it may not hit first
            add_foul_mark(f.aim, c.session().state().positions.at(*preview->first_ball), Rf);
        const rules::Call call = c.call();
        if (call.is_ball() && c.session().state().has(call.ball))
            add_call_marks(f.aim, c.session().table(), c.session().state().positions.at(call.ball),
                           call.pocket, Rf);
        f.show_aim = aim_guide != AimGuide::off || !f.aim.marks.empty();
    }
    // The stroke: before the strike the cue moves from where it was drawn back to the ball.
    if (c.moving() && c.playback().time() < 0.0)
        if (const std::optional<Controller::StrokeShown> k = last_stroke(c))
            f.cue = stroke_cue(*k, c.playback().time());
    const rules::BallInHand in_hand = c.session().ball_in_hand();
    if (c.human_to_act() && in_hand != rules::BallInHand::none &&
        cue != c.session().state().positions.end()) {
        render::BallInHandView h;
        const bool refused = dragged_to && c.check_cue_ball(*dragged_to).has_value();
        const physics::Vec2 at = refused ? *dragged_to : cue->second;
        h.pos = {static_cast<float>(at.x), static_cast<float>(at.y)};
        h.legal = !refused;
        h.kitchen_only = in_hand == rules::BallInHand::kitchen;
        if (const game::SnookerSession* s = c.snooker()) {
            const physics::SnookerMarkings& m = s->marks().marks;
            h.d_only = glm::vec3(static_cast<float>(m.baulk_x), static_cast<float>(m.d_centre().y),
                                 static_cast<float>(m.d_radius));
        }
        f.ball_in_hand = h;
    }
    return f;
}

}  // namespace app
