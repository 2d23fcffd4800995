#include "app/input.hpp"

#include <cmath>

namespace app {

namespace {
constexpr double click_slop = 3.0;  // a press and release closer than this is a click (unit: px)
}

void TableInput::press(MouseButton b, double x, double y) {
    if (drag_ != Drag::none) return;
    start_x_ = last_x_ = x;
    start_y_ = last_y_ = y;
    moved_ = false;
    switch (b) {
        case MouseButton::right:
            drag_ = Drag::aim_and_strike;
            break;
        case MouseButton::middle:
            drag_ = Drag::orbit;
            break;
        case MouseButton::left:
            press_left(x, y);
            break;
    }
}

// Aim, or drag the ball under the mouse: the cue ball in hand, or in practice any ball.
void TableInput::press_left(double x, double y) {
    drag_ = Drag::aim;
    if (!c_.human_to_act()) return;
    const bool in_hand = c_.session().ball_in_hand() != rules::BallInHand::none;
    if (!in_hand && !c_.practicing()) return;
    const std::optional<physics::Vec2> p = to_table_(x, y);
    if (!p) return;
    const double R = c_.session().config().params.ball_radius;
    for (const auto& [id, pos] : c_.session().state().positions) {
        if ((id != 0 && !c_.practicing()) || physics::norm(*p - pos) >= (id == 0 ? 2.0 : 1.0) * R)
            continue;
        drag_ = c_.practicing() ? Drag::ball : Drag::cue_ball;
        ball_ = id;
        dragged_to_ = p;
        return;
    }
}

void TableInput::motion(double x, double y, bool shift) {
    const double dx = x - last_x_, dy = y - last_y_;
    last_x_ = x;
    last_y_ = y;
    if (std::hypot(x - start_x_, y - start_y_) > click_slop) moved_ = true;
    switch (drag_) {
        case Drag::none:
            break;
        case Drag::aim_and_strike:
        case Drag::aim:
            // Mouse to the right turns the aim to the right (clockwise seen from above).
            c_.turn_aim(-dx * (shift ? sensitivity.fine : sensitivity.normal));
            break;
        case Drag::cue_ball:
            dragged_to_ = to_table_(x, y);
            if (dragged_to_) c_.move_cue_ball(*dragged_to_);
            break;
        case Drag::ball:
            if (const std::optional<physics::Vec2> p = to_table_(x, y)) c_.move_ball(ball_, *p);
            break;
        case Drag::orbit:
            rig_.orbit(static_cast<float>(dx), static_cast<float>(dy));
            break;
    }
}

void TableInput::release(MouseButton b, double x, double y) {
    const Drag d = drag_;
    const bool matches =
        (b == MouseButton::right && d == Drag::aim_and_strike) ||
        (b == MouseButton::middle && d == Drag::orbit) ||
        (b == MouseButton::left && (d == Drag::aim || d == Drag::cue_ball || d == Drag::ball));
    if (!matches) return;
    drag_ = Drag::none;
    if (d == Drag::aim_and_strike) {
        c_.strike();
    } else if (d == Drag::aim && !moved_) {
        if (const std::optional<physics::Vec2> p = to_table_(x, y)) c_.click_table(*p);
    }
}

}  // namespace app
