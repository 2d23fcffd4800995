// The mouse and keyboard at the table (the original game's controls, plus fine aim): turns
// drags, clicks, the wheel and keys into controller and camera calls. No SDL here: the window
// translates its events into these calls, so the controls are testable on their own.
#pragma once

#include <functional>
#include <optional>

#include "app/camera_rig.hpp"
#include "app/controller.hpp"

namespace app {

enum class MouseButton { left, middle, right };

/// Degrees of aim per pixel of horizontal mouse motion (unit: deg/px).
struct AimSensitivity {
    double normal = 0.1;
    double fine = 0.01;  ///< with Shift: 0.05° is 5 px
};

/// What a mouse gesture in the table view does.
class TableInput {
  public:
    /// `to_table` maps a pixel of the view to a point on the table (empty off the table plane).
    using ToTable = std::function<std::optional<physics::Vec2>(double x, double y)>;

    TableInput(Controller& controller, CameraRig& rig, ToTable to_table)
        : c_(controller), rig_(rig), to_table_(std::move(to_table)) {}

    /// Right button: aim while held, strike on release. Left: aim without striking, or drag
    /// the cue ball in hand when pressed on it (in practice: any ball), or a click (no motion)
    /// to call a ball/pocket.
    /// Middle: orbit the free camera.
    void press(MouseButton b, double x, double y);
    void motion(double x, double y, bool shift);
    void release(MouseButton b, double x, double y);
    void wheel(float steps) { rig_.zoom(steps); }
    bool dragging() const { return drag_ != Drag::none; }
    /// The cue ball in hand is being moved, and where it would go (for the legal/illegal look).
    bool moving_cue_ball() const { return drag_ == Drag::cue_ball; }
    /// While the cue ball in hand is dragged: the point under the mouse, legal or not.
    std::optional<physics::Vec2> dragged_to() const {
        return drag_ == Drag::cue_ball ? dragged_to_ : std::nullopt;
    }

    AimSensitivity sensitivity;

  private:
    enum class Drag { none, aim_and_strike, aim, cue_ball, ball, orbit };
    void press_left(double x, double y);
    Controller& c_;
    CameraRig& rig_;
    ToTable to_table_;
    Drag drag_ = Drag::none;
    double start_x_ = 0, start_y_ = 0, last_x_ = 0, last_y_ = 0;
    bool moved_ = false;
    int ball_ = 0;  ///< the ball dragged in practice
    std::optional<physics::Vec2> dragged_to_;
};

}  // namespace app
