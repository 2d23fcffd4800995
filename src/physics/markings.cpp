#include "physics/markings.hpp"

#include <cmath>

namespace physics {

namespace {
constexpr double kSnookerLength = 3.569, kSnookerWidth = 1.778;  // WPBSA 1(a) (unit: m)
constexpr double kCaromWidth = 1.420;                            // UMB (unit: m)
constexpr double kCaromStartOffset = 0.1825;  ///< starting spot beside the bottom spot (unit: m)
}  // namespace

SnookerMarkings snooker_markings(const Table& table) {
    SnookerMarkings m;
    const double sx = table.length() / kSnookerLength, sy = table.width() / kSnookerWidth;
    m.baulk_x *= sx;
    m.black_from_top *= sx;
    m.d_radius *= sy;
    m.length = table.length();
    m.width = table.width();
    return m;
}

Vec2 SnookerMarkings::spot(int colour) const {
    const double mid = width / 2.0;
    switch (colour) {
        case snooker_ball::yellow:
            return {baulk_x, mid - d_radius};
        case snooker_ball::green:
            return {baulk_x, mid + d_radius};
        case snooker_ball::brown:
            return {baulk_x, mid};
        case snooker_ball::blue:
            return {length / 2.0, mid};
        case snooker_ball::pink:
            return {0.75 * length, mid};  // midway between the centre spot and the top cushion
        default:
            return {length - black_from_top, mid};
    }
}

bool SnookerMarkings::in_d(Vec2 p) const {
    constexpr double tol = 1e-9;
    return p.x <= baulk_x + tol && norm(p - d_centre()) <= d_radius + tol;
}

CaromSpots carom_spots(const Table& table) {
    const double L = table.length(), mid = table.width() / 2.0;
    const double off = kCaromStartOffset * table.width() / kCaromWidth;
    return {{0.75 * L, mid}, {0.25 * L, mid}, {0.25 * L, mid + off}, {0.25 * L, mid - off}};
}

}  // namespace physics
