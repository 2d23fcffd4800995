// All physical constants of the simulation, in one place, with their units (docs/physics.md).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace physics {

struct Params {
    double ball_radius = 0.028575;  ///< R (unit: m); WPA ball, 2 1/4 in
    double ball_mass = 0.170;       ///< m (unit: kg)
    double gravity = 9.81;          ///< g (unit: m/s²)
    double mu_slide = 0.2;          ///< ball–cloth sliding friction (unit: 1)
    double mu_roll = 0.01;          ///< ball–cloth rolling resistance (unit: 1)
    double spin_decel = 10.9;       ///< deceleration of spin about z (unit: rad/s²)
    double e_ball = 0.95;           ///< ball–ball restitution (unit: 1)
    /// Ball–ball friction (unit: 1). Empty: the speed-dependent fit
    /// μ(v) = 0.00995 + 0.108·exp(−1.088·v), v the contact slip speed in m/s
    /// (Alciatore, TP A.14, from Marlow's data).
    std::optional<double> mu_ball;
    double e_cushion = 0.85;     ///< ball–cushion restitution (unit: 1)
    double mu_cushion = 0.2;     ///< ball–cushion friction (unit: 1)
    double cue_mass = 0.567;     ///< cue stick mass (unit: kg); 20 oz
    double cue_tip_e = 0.75;     ///< cue tip–ball restitution (unit: 1)
    double cue_endmass = 0.015;  ///< effective end mass of the cue, for squirt (unit: kg)
    double miscue_limit = 0.5;   ///< largest tip offset that does not miscue (unit: fraction of R)
};

/// The ball sets: "pool" (the defaults above), "snooker" (52.5 mm balls, napped cloth),
/// "carom" (61.5 mm balls, heated cloth); sources in docs/physics.md. Empty for another name.
std::optional<Params> params_preset(std::string_view name);
inline constexpr std::array<std::string_view, 3> params_preset_names{"pool", "snooker", "carom"};

/// Ball–ball collision model.
enum class BallBallModel {
    frictional,    ///< restitution + capped Coulomb friction at the contact (throw, spin transfer)
    frictionless,  ///< normal impulse only
};

/// Ball–cushion collision model (also used for jaw facings and jaw noses).
enum class CushionModel {
    han2005,  ///< Han 2005: impulse at the cushion nose above the ball's centre, with friction
    simple,   ///< mirror bounce: normal velocity × −e_cushion, tangential velocity and spin kept
};

struct Models {
    BallBallModel ball_ball = BallBallModel::frictional;
    CushionModel cushion = CushionModel::han2005;
};

/// The latest time an event may have (unit: s): a shot with a later one is truncated. Real shots
/// end within a minute; only a friction of zero keeps balls going that long (traps_test).
inline constexpr double kHorizon = 1e6;

/// Options of one simulation that are not physical constants.
struct SimOptions {
    Models models;
    std::size_t max_events = 100000;  ///< cap on events per shot; reaching it truncates the shot
};

}  // namespace physics
