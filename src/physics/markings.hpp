// The marks on the cloth that the snooker and carom games use: the baulk line, the D and the
// colour spots (WPBSA Rules, Section 1, 1(d)–(f)), and the carom spots (UMB). Frame:
// docs/cli.md (x from the baulk / bottom cushion, y to the left seen from there).
#pragma once

#include "physics/table.hpp"
#include "physics/vec.hpp"

namespace physics {

/// Snooker ball ids: 0 the cue ball, 1–15 the reds, then the colours.
namespace snooker_ball {
inline constexpr int cue = 0;
inline constexpr int first_red = 1;
inline constexpr int last_red = 15;
inline constexpr int yellow = 16;
inline constexpr int green = 17;
inline constexpr int brown = 18;
inline constexpr int blue = 19;
inline constexpr int pink = 20;
inline constexpr int black = 21;
}  // namespace snooker_ball

constexpr bool is_red(int id) {
    return id >= snooker_ball::first_red && id <= snooker_ball::last_red;
}
constexpr bool is_colour(int id) {
    return id >= snooker_ball::yellow && id <= snooker_ball::black;
}
/// A snooker ball's value: red 1, yellow 2 … black 7; 0 for the cue ball.
constexpr int snooker_value(int id) {
    return is_red(id) ? 1 : is_colour(id) ? id - snooker_ball::yellow + 2 : 0;
}

/// The snooker marks, scaled from the 12 ft table's to the table's length and width.
struct SnookerMarkings {
    double baulk_x = 0.737;         ///< the baulk line, from the bottom cushion (unit: m)
    double d_radius = 0.292;        ///< the D, a half circle behind the baulk line (unit: m)
    double black_from_top = 0.324;  ///< the black spot, from the top cushion (unit: m)
    double length = 3.569, width = 1.778;

    Vec2 d_centre() const { return {baulk_x, width / 2.0}; }
    /// The spot of a colour (ids 16–21): yellow right of the D seen from baulk (−y), green left.
    Vec2 spot(int colour) const;
    /// Whether a ball centre lies in the D (its line and arc included).
    bool in_d(Vec2 p) const;
};
SnookerMarkings snooker_markings(const Table& table);

/// Carom ball ids: the white (the first shooter's cue ball), the yellow, the red.
namespace carom_ball {
inline constexpr int white = 0;
inline constexpr int yellow = 1;
inline constexpr int red = 2;
}  // namespace carom_ball

/// The UMB spots on the long string: the top spot (red), the bottom spot (the opponent's
/// ball), and the two starting spots either side of it on the head string.
struct CaromSpots {
    Vec2 top, bottom, start_left, start_right;
};
CaromSpots carom_spots(const Table& table);

}  // namespace physics
