// The size a moving camera's frames are drawn at (a fraction of the window, scaled up after):
// lowered in steps while those frames take longer than their budget and raised again while
// they take well under it, between a floor and a ceiling. On a fast machine it stays at the
// ceiling; on a slow or busy one the picture softens while the camera moves instead of the
// frame rate falling. A still camera is always drawn in full.
#pragma once

namespace render {

class MovingScale {
  public:
    /// `highest` and `lowest`: the fractions of the size (0.1–1); `budget_ms`: the time a
    /// moving frame's drawing should take (unit: ms). lowest ≥ highest keeps it fixed.
    MovingScale(float highest, float lowest, double budget_ms);

    float scale() const { return scale_; }
    /// A moving frame took `ms` to draw at scale(): the next one's scale.
    void record(double ms);

  private:
    float highest_, lowest_;
    double budget_ms_;
    double average_ms_ = -1.0;  ///< exponential average of the recent moving frames (unit: ms)
    float scale_;
};

}  // namespace render
