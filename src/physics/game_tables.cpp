// The snooker and carom tables and ball sets (docs/physics.md, "Snooker and carom tables"):
// dimensions from the WPBSA and UMB rules, the rest estimates said to be so there.
#include <cmath>

#include "physics/params.hpp"
#include "physics/table.hpp"

namespace physics {

TableSpec snooker_table_spec() {
    TableSpec s;
    s.length = 3.569;  // WPBSA Rules, Section 1, 1(a)
    s.width = 1.778;
    // Nose tip to nose tip before rounding; with the 35 mm noses the narrowest gaps are
    // 89 mm (corner) and 105 mm (middle): estimates, the WPBSA templates are not published.
    s.corner_mouth = 0.0915;
    s.side_mouth = 0.1163;
    s.corner_facing_deg = 140.0;
    s.side_facing_deg = 100.0;
    s.jaw_nose_radius = 0.035;  // the rounded cushion knuckle (estimate)
    s.cushion_height = 0.0333;  // 63.5 % of 2R, as for pool (estimate)
    return s;
}

TableSpec carom_table_spec() {
    TableSpec s;
    s.length = 2.840;  // UMB match table, 2840 × 1420 mm
    s.width = 1.420;
    s.cushion_height = 0.037;  // UMB: 37 mm ± 1 mm
    s.pockets = false;
    return s;
}

std::optional<Params> params_preset(std::string_view name) {
    Params p;
    if (name == "pool") return p;
    // Spin about z decays as 5·μ_sp·g / (2R) (the spinning-friction model, as in pooltool):
    // the pool figure, same cloth friction, scaled by 1/R.
    const double pool_spin_decel_r = p.spin_decel * p.ball_radius;
    if (name == "snooker") {
        p.ball_radius = 0.02625;  // WPBSA Rules, Section 1, 2: 52.5 mm
        p.ball_mass = 0.142;      // a set within 3 g of each other (WPBSA); 142 g: estimate
        p.mu_roll = 0.012;        // napped wool cloth, slower than pool cloth (estimate)
        p.e_cushion = 0.80;       // estimate
        p.spin_decel = pool_spin_decel_r / p.ball_radius;
        return p;
    }
    if (name == "carom") {
        p.ball_radius = 0.03075;  // UMB: 61.5 mm
        p.ball_mass = 0.210;      // UMB: 205 to 220 g
        p.mu_roll = 0.006;        // heated, smooth cloth: lower rolling resistance (estimate)
        p.e_cushion = 0.90;       // carom cushions are livelier (estimate)
        p.spin_decel = pool_spin_decel_r / p.ball_radius;
        return p;
    }
    return std::nullopt;
}

}  // namespace physics
