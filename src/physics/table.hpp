// Table geometry: the playing surface, cushions, pocket jaws and drop regions, built from a
// specification (presets 7ft, 8ft, 9ft: WPA; snooker12ft: WPBSA; carom10ft: UMB). Frame and names:
// docs/cli.md.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "physics/vec.hpp"

namespace physics {

/// The user-facing dimensions of a table (all lengths in m, angles in degrees).
struct TableSpec {
    double length = 2.540;        ///< L, cushion nose to cushion nose along x (unit: m)
    double width = 1.270;         ///< W, along y (unit: m)
    double corner_mouth = 0.116;  ///< corner pocket mouth, nose tip to nose tip (unit: m)
    double side_mouth = 0.1285;   ///< side pocket mouth (unit: m)
    double corner_facing_deg =
        142.0;  ///< angle of a corner jaw facing to its cushion line (unit: deg)
    double side_facing_deg = 104.0;  ///< angle of a side jaw facing to its cushion line (unit: deg)
    double jaw_nose_radius = 0.005;  ///< radius of the rounded jaw noses (unit: m)
    double cushion_height =
        0.036290;  ///< cushion nose height above the cloth (unit: m); 63.5 % of 2R
    double corner_shelf =
        0.0286;  ///< depth of the slate's pocket edge behind a corner mouth (unit: m)
    double side_shelf = 0.0048;  ///< depth of the slate's pocket edge behind a side mouth (unit: m)
    double jaw_depth = 0.0635;   ///< length of a jaw facing into the cushion (unit: m)
    bool pockets = true;         ///< false: closed rails, no pockets
    bool bounded = true;         ///< false: "unbounded", no cushions and no pockets
};

/// The named presets: "7ft", "8ft", "9ft", "snooker12ft", "carom10ft", "unbounded". Empty for
/// an unknown name.
std::optional<TableSpec> table_preset(std::string_view name);
/// The preset names, in the order above.
inline constexpr std::array<std::string_view, 6> table_preset_names{
    "7ft", "8ft", "9ft", "snooker12ft", "carom10ft", "unbounded"};

/// A 12 ft snooker table (WPBSA: playing area 3569 × 1778 mm) with rounded pocket jaws; the
/// pocket figures are estimates (docs/physics.md, "Snooker and carom tables").
TableSpec snooker_table_spec();
/// A 10 ft carom table (UMB: 2840 × 1420 mm), no pockets, cushion nose 37 mm high.
TableSpec carom_table_spec();

/// Pockets, by compass direction (x east, y north).
enum class PocketId : int { SW = 0, S = 1, SE = 2, NW = 3, N = 4, NE = 5 };
/// Rails (cushions between pockets).
enum class RailId : int { W = 0, E = 1, SW_S = 2, S_SE = 3, NW_N = 4, N_NE = 5 };

std::string_view pocket_name(int pocket);
std::string_view rail_name(int rail);
std::optional<int> pocket_from_name(std::string_view name);

/// A straight cushion face: a ball's centre touches it at distance R on the `normal` side.
struct CushionLine {
    Vec2 a, b;        ///< end points of the face (unit: m)
    Vec2 dir;         ///< unit vector from a to b
    Vec2 normal;      ///< unit normal pointing to where the balls are
    double length;    ///< |b − a| (unit: m)
    int rail = -1;    ///< rail index for a rail face, else −1
    int pocket = -1;  ///< pocket index for a jaw facing, else −1
};

/// A rounded jaw nose: a cylinder of radius `radius` about `centre`.
struct JawNose {
    Vec2 centre;
    double radius;
    int pocket;
};

/// A pocket: the mouth between its nose tips, and the drop line behind it. A ball whose centre
/// crosses the drop line (moving along `inward`) falls.
struct Pocket {
    int id;
    Vec2 mouth_a, mouth_b;  ///< the two nose tips (sharp corners before rounding)
    Vec2 drop_point;        ///< a point on the drop line
    Vec2 inward;            ///< unit normal of the drop line, pointing into the pocket
    Vec2 centre;            ///< middle of the hole (for drawing and aiming)
};

struct Table {
    TableSpec spec;
    std::vector<CushionLine> lines;
    std::vector<JawNose> noses;
    std::vector<Pocket> pockets;

    double length() const { return spec.length; }
    double width() const { return spec.width; }
    Vec2 head_spot() const { return {spec.length / 4.0, spec.width / 2.0}; }
    Vec2 foot_spot() const { return {3.0 * spec.length / 4.0, spec.width / 2.0}; }
    /// Whether a ball centre at p rests on the playing surface (within the cushions, by R).
    bool on_surface(Vec2 p, double ball_radius) const;
};

/// Builds the geometry from a specification. The spec must be valid (see validate_table_spec).
Table build_table(const TableSpec& spec);

/// Empty if valid, else a message naming the field (e.g. "corner_mouth: must be larger than a
/// ball").
std::optional<std::string> validate_table_spec(const TableSpec& spec, double ball_radius);

}  // namespace physics
