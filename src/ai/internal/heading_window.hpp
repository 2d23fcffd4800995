// Strokes that pot without noise, moved to the middle of their window of headings: the range of
// headings around the stroke's at which it still pots the same. Where the heading's noise is
// what makes a stroke miss, the middle of that window is the heading most likely to pot.
//   kicks  the sweep's headings are half a degree apart (candidates.hpp), and the headings at
//          which a kick or a bank still pots often span less than that, so the sweep's heading
//          may lie near an edge, where much of the noise misses;
//   pots   a pot's heading is refined to send the object ball at a point behind the pocket's
//          mouth (aim.hpp), but the jaws, the far cushion and the other balls make the window
//          of headings that pot lopsided around it.
// heading_window_test.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "ai/internal/candidates.hpp"
#include "ai/internal/evaluate.hpp"
#include "ai/internal/private.hpp"

namespace ai {

/// How a window's edges are looked for: steps out from the stroke's heading, `first_step_deg`
/// then each `growth` times the last (1: equal steps), never more than `reach_deg` away; then
/// the last step is halved `halvings` times between the last heading that pots and the first
/// that does not.
struct WindowSearch {
    double first_step_deg = 0.05;  ///< (unit: deg)
    double growth = 1.0;
    double reach_deg = 0.6;  ///< (unit: deg)
    int halvings = 3;
};
/// Kicks: equal steps of 0.05° (a tenth of the sweep's) up to 0.6°, edges to 0.006°.
inline constexpr WindowSearch kick_window_search{0.05, 1.0, 0.6, 3};
/// Pots: steps from 0.01° doubling up to 0.64°, edges to a sixteenth of the last step.
inline constexpr WindowSearch pot_window_search{0.01, 2.0, 0.64, 4};

/// The edges of the window of headings around `c`'s at which it pots as played without noise:
/// the shooter stays at the table, with the same call (a kick's call is that of what it pots).
/// `c` must pot without noise. Adds its simulations.
struct HeadingWindow {
    double low_deg = 0.0, high_deg = 0.0;  ///< (unit: deg)
};
HeadingWindow heading_window(const Evaluator& eval, const Candidate& c, const WindowSearch& search,
                             std::int64_t& simulations);

/// `c` turned to the middle of its window; empty where it does not pot without noise, or
/// where the middle does not. Adds its simulations.
std::optional<Candidate> centred(const Evaluator& eval, const Candidate& c,
                                 const WindowSearch& search, std::int64_t& simulations);

/// For up to `count` kicks of `kicks` that pot without noise (`nominal[i].stays`), the best
/// first by their nominal value: the same kick in the middle of its window, and at each other
/// of `kick_speed_factors` × its speed where it still pots there, centred again. With
/// `max_raise_deg` > 0 each of those also on a cue raised up to that, to where the swerve of a
/// side-offset error cancels its squirt (aim.hpp's `kick_compensating_elevation`; the ball's
/// speed kept), centred again where it still pots. None on a stroke already tried. Adds the
/// simulations; `workers` threads.
inline constexpr std::array<double, 3> kick_speed_factors{1.0, 0.8, 1.25};
std::vector<Candidate> centred_kicks(const Evaluator& eval, const std::vector<Candidate>& kicks,
                                     const std::vector<Score>& nominal, std::size_t count,
                                     double max_raise_deg, std::int64_t& simulations,
                                     Workers workers);

}  // namespace ai
