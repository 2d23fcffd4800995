#include "physics/table.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "physics/portable_math.hpp"

namespace physics {

namespace {

constexpr std::array<std::string_view, 6> kPocketNames = {"SW", "S", "SE", "NW", "N", "NE"};
constexpr std::array<std::string_view, 6> kRailNames = {"W", "E", "SW-S", "S-SE", "NW-N", "N-NE"};

Vec2 unit(Vec2 v) {
    return (1.0 / norm(v)) * v;
}

CushionLine make_line(Vec2 a, Vec2 b, Vec2 normal, int rail, int pocket) {
    Vec2 d = b - a;
    double len = norm(d);
    return {a, b, (1.0 / len) * d, normal, len, rail, pocket};
}

/// One nose tip of a pocket: where a rail face meets a jaw facing.
struct NoseTip {
    Vec2 tip;         ///< the sharp corner, from which the mouth is measured
    Vec2 along_rail;  ///< unit direction along the rail face, away from the pocket
    Vec2 normal;      ///< the rail face's normal, into the table
};

/// Rounds the corner at a nose tip and adds the jaw facing and the nose. Returns the point
/// where the rail face now ends (the tangent point of the rounding).
Vec2 add_jaw(Table& t, const NoseTip& n, double facing_deg, int pocket) {
    const double alpha = facing_deg * std::numbers::pi / 180.0;
    // The facing runs into the cushion at angle alpha to the rail face.
    Vec2 f = portable::cos(alpha) * n.along_rail - portable::sin(alpha) * n.normal;
    const double r = t.spec.jaw_nose_radius;
    const double half = alpha / 2.0;
    const double tangent = r / portable::tan(half);
    Vec2 rail_end = n.tip + tangent * n.along_rail;
    Vec2 facing_start = n.tip + tangent * f;
    Vec2 facing_end = n.tip + t.spec.jaw_depth * f;
    // The facing's normal points away from the cushion material (which lies toward the rail).
    Vec2 m = perp(f);
    if (dot(m, n.along_rail) > 0) m = -m;
    if (t.spec.jaw_depth > tangent)
        t.lines.push_back(make_line(facing_start, facing_end, m, -1, pocket));
    if (r > 0) {
        Vec2 bisector = unit(n.along_rail + f);
        t.noses.push_back({n.tip + (r / portable::sin(half)) * bisector, r, pocket});
    }
    return rail_end;
}

void add_pocket(Table& t, int id, const NoseTip& a, const NoseTip& b, double facing_deg,
                double shelf) {
    Vec2 inward = unit(-1.0 * (a.normal + b.normal));
    Vec2 mid = 0.5 * (a.tip + b.tip);
    Vec2 drop = mid + shelf * inward;
    t.pockets.push_back({id, a.tip, b.tip, drop, inward, drop + t.spec.jaw_depth * 0.5 * inward});
    (void)facing_deg;
}

}  // namespace

std::string_view pocket_name(int pocket) {
    return pocket >= 0 && pocket < 6 ? kPocketNames[static_cast<std::size_t>(pocket)] : "?";
}

std::string_view rail_name(int rail) {
    return rail >= 0 && rail < 6 ? kRailNames[static_cast<std::size_t>(rail)] : "?";
}

std::optional<int> pocket_from_name(std::string_view name) {
    for (std::size_t i = 0; i < kPocketNames.size(); ++i)
        if (kPocketNames[i] == name) return static_cast<int>(i);
    return std::nullopt;
}

std::optional<TableSpec> table_preset(std::string_view name) {
    TableSpec s;
    if (name == "9ft") return s;
    if (name == "8ft") {
        s.length = 2.3368;
        s.width = 1.1684;
        return s;
    }
    if (name == "7ft") {
        s.length = 1.9812;
        s.width = 0.9906;
        return s;
    }
    if (name == "snooker12ft") return snooker_table_spec();
    if (name == "carom10ft") return carom_table_spec();
    if (name == "unbounded") {
        s.bounded = false;
        s.pockets = false;
        return s;
    }
    return std::nullopt;
}

namespace {

/// A rounded nose must fit on its jaw facing and leave some rail: its tangent points lie
/// r / tan(α/2) from the sharp tip (table.cpp, add_jaw).
std::optional<std::string> check_rounding(const TableSpec& s) {
    if (s.jaw_nose_radius <= 0.02) return std::nullopt;  // the pool range, always valid
    for (double deg : {s.corner_facing_deg, s.side_facing_deg}) {
        const double tangent = s.jaw_nose_radius / std::tan(deg * std::numbers::pi / 360.0);
        if (tangent >= s.jaw_depth)
            return "jaw_nose_radius: too large for the jaws (its rounding must end within "
                   "jaw_depth)";
    }
    return std::nullopt;
}

}  // namespace

std::optional<std::string> validate_table_spec(const TableSpec& s, double ball_radius) {
    auto finite_positive = [](double v) { return std::isfinite(v) && v > 0; };
    if (!s.bounded) return std::nullopt;
    const double d = 2.0 * ball_radius;
    if (!finite_positive(s.length) || s.length < 4 * d)
        return "length: must be at least 4 ball diameters";
    if (!finite_positive(s.width) || s.width < 4 * d)
        return "width: must be at least 4 ball diameters";
    if (s.width > s.length) return "width: must not exceed length";
    // Every rail has a nose, pockets or not.
    if (!(std::isfinite(s.cushion_height) && s.cushion_height >= ball_radius &&
          s.cushion_height < 2 * ball_radius))
        return "cushion_height: must be from R to 2R (the nose meets the ball above its centre)";
    if (!s.pockets) return std::nullopt;
    if (!finite_positive(s.corner_mouth) || s.corner_mouth <= d || s.corner_mouth > s.width / 4)
        return "corner_mouth: must be wider than a ball and at most a quarter of the width";
    if (!finite_positive(s.side_mouth) || s.side_mouth <= d || s.side_mouth > s.length / 4)
        return "side_mouth: must be wider than a ball and at most a quarter of the length";
    if (!(s.corner_facing_deg >= 90 && s.corner_facing_deg <= 170))
        return "corner_facing_deg: must be from 90 to 170";
    if (!(s.side_facing_deg >= 90 && s.side_facing_deg <= 170))
        return "side_facing_deg: must be from 90 to 170";
    if (!(std::isfinite(s.jaw_nose_radius) && s.jaw_nose_radius >= 0 && s.jaw_nose_radius <= 0.05))
        return "jaw_nose_radius: must be from 0 to 0.05 m";
    if (!(std::isfinite(s.corner_shelf) && s.corner_shelf >= 0 && s.corner_shelf <= 0.1))
        return "corner_shelf: must be from 0 to 0.1 m";
    if (!(std::isfinite(s.side_shelf) && s.side_shelf >= 0 && s.side_shelf <= 0.1))
        return "side_shelf: must be from 0 to 0.1 m";
    if (!(std::isfinite(s.jaw_depth) && s.jaw_depth > s.corner_shelf + 0.01 &&
          s.jaw_depth > s.side_shelf + 0.01 && s.jaw_depth <= 0.2))
        return "jaw_depth: must exceed the shelves by 0.01 m and be at most 0.2 m";
    return check_rounding(s);
}

Table build_table(const TableSpec& spec) {
    Table t;
    t.spec = spec;
    if (!spec.bounded) return t;
    const double L = spec.length, W = spec.width;
    const Vec2 east{1, 0}, west{-1, 0}, north{0, 1}, south{0, -1};
    const int w = static_cast<int>(RailId::W), e = static_cast<int>(RailId::E);
    const int sws = static_cast<int>(RailId::SW_S), sse = static_cast<int>(RailId::S_SE);
    const int nwn = static_cast<int>(RailId::NW_N), nne = static_cast<int>(RailId::N_NE);
    if (!spec.pockets) {
        t.lines.push_back(make_line({0, 0}, {0, W}, east, w, -1));
        t.lines.push_back(make_line({L, 0}, {L, W}, west, e, -1));
        t.lines.push_back(make_line({0, 0}, {L / 2, 0}, north, sws, -1));
        t.lines.push_back(make_line({L / 2, 0}, {L, 0}, north, sse, -1));
        t.lines.push_back(make_line({0, W}, {L / 2, W}, south, nwn, -1));
        t.lines.push_back(make_line({L / 2, W}, {L, W}, south, nne, -1));
        return t;
    }
    const double c = spec.corner_mouth / std::sqrt(2.0);
    const double s = spec.side_mouth / 2.0;
    const double cf = spec.corner_facing_deg, sf = spec.side_facing_deg;
    const int SW = 0, S = 1, SE = 2, NW = 3, N = 4, NE = 5;
    // Nose tips: {tip, direction along the rail away from the pocket, rail normal}.
    const NoseTip sw_s{{c, 0}, east, north}, sw_w{{0, c}, north, east};
    const NoseTip s_w{{L / 2 - s, 0}, west, north}, s_e{{L / 2 + s, 0}, east, north};
    const NoseTip se_s{{L - c, 0}, west, north}, se_e{{L, c}, north, west};
    const NoseTip nw_n{{c, W}, east, south}, nw_w{{0, W - c}, south, east};
    const NoseTip n_w{{L / 2 - s, W}, west, south}, n_e{{L / 2 + s, W}, east, south};
    const NoseTip ne_n{{L - c, W}, west, south}, ne_e{{L, W - c}, south, west};

    // Rails, each between the rounded noses of its two pockets.
    auto rail = [&](const NoseTip& from, double fdeg, int fp, const NoseTip& to, double tdeg,
                    int tp, int id) {
        Vec2 a = add_jaw(t, from, fdeg, fp);
        Vec2 b = add_jaw(t, to, tdeg, tp);
        t.lines.push_back(make_line(a, b, from.normal, id, -1));
    };
    rail(sw_w, cf, SW, nw_w, cf, NW, w);
    rail(se_e, cf, SE, ne_e, cf, NE, e);
    rail(sw_s, cf, SW, s_w, sf, S, sws);
    rail(s_e, sf, S, se_s, cf, SE, sse);
    rail(nw_n, cf, NW, n_w, sf, N, nwn);
    rail(n_e, sf, N, ne_n, cf, NE, nne);

    add_pocket(t, SW, sw_s, sw_w, cf, spec.corner_shelf);
    add_pocket(t, S, s_w, s_e, sf, spec.side_shelf);
    add_pocket(t, SE, se_s, se_e, cf, spec.corner_shelf);
    add_pocket(t, NW, nw_n, nw_w, cf, spec.corner_shelf);
    add_pocket(t, N, n_w, n_e, sf, spec.side_shelf);
    add_pocket(t, NE, ne_n, ne_e, cf, spec.corner_shelf);
    return t;
}

namespace {

constexpr double kSurfaceTolerance = 1e-9;  ///< (unit: m) touching a cushion is on the bed

/// Whether p is at a pocket's mouth: in front of its drop line; if past the mouth line (in the
/// throat), between the nose tips; if in front of it, by at most R and at most R beyond either
/// tip (a ball resting against a nose). Farther out, a centre off the rectangle is in a rail.
bool at_mouth(const Pocket& pk, Vec2 p, double R) {
    const Vec2 mid = 0.5 * (pk.mouth_a + pk.mouth_b);
    const double half = 0.5 * norm(pk.mouth_b - pk.mouth_a);
    if (dot(p - pk.drop_point, pk.inward) >= 0) return false;
    const double past = dot(p - mid, pk.inward);
    if (past < -(R + kSurfaceTolerance)) return false;
    return std::fabs(cross(pk.inward, p - mid)) < (past > 0 ? half : half + R);
}

/// Whether a ball at p is clear of the rails and of the facings and noses of pocket `pk`.
bool clear_of_cushions(const Table& t, const Pocket& pk, Vec2 p, double R) {
    for (const CushionLine& l : t.lines) {
        if (l.pocket != pk.id && l.rail < 0) continue;
        const double along = dot(p - l.a, l.dir);
        const double off = dot(p - l.a, l.normal);
        if (along >= 0 && along <= l.length && off < R - kSurfaceTolerance) return false;
    }
    for (const JawNose& n : t.noses)
        if (n.pocket == pk.id && norm(p - n.centre) < R + n.radius - kSurfaceTolerance)
            return false;
    return true;
}

}  // namespace

bool Table::on_surface(Vec2 p, double R) const {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
    if (!spec.bounded) return true;
    constexpr double tol = kSurfaceTolerance;
    const double L = spec.length, W = spec.width;
    if (p.x >= R - tol && p.x <= L - R + tol && p.y >= R - tol && p.y <= W - R + tol) return true;
    for (const Pocket& pk : pockets)
        if (at_mouth(pk, p, R) && clear_of_cushions(*this, pk, p, R)) return true;
    return false;
}

}  // namespace physics
