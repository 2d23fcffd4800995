// Collision models: impulses at an instant of contact. Private to physics.
#pragma once

#include "physics/ball_state.hpp"
#include "physics/internal/private.hpp"
#include "physics/params.hpp"

namespace physics::collide {

// Chatter (docs/physics.md, trap 3). Friction can keep two touching bodies accelerating into
// each other (a spinning ball driving into another, or into a cushion); an event-based engine
// then sees ever smaller bounces. Between two balls the rules that keep the events per contact
// few are decided by the time between contacts, not by a speed, so that a slow collision that
// nothing drives keeps its restitution
// (Traps.NewtonsCradleWithRestitutionMatchesSequentialImpulses):
/// Contacts closer together in time than this are one resting contact (unit: s; the gaps it
/// opens stay under 25 µm): a bounce that the contact's own (relative) acceleration would
/// bring back within it is perfectly inelastic, and a "pushing" contact (touching, no approach
/// speed, accelerating into contact) is separated just fast enough to return after it, with
/// the energy that takes removed from the balls' motion.
inline constexpr double kContactTime = 0.01;
/// Least separation speed of a pushing contact (unit: m/s); each ball gets half of it, which
/// must stay above motion::kRestSpeed so the separation is not settled away.
inline constexpr double kSeparationSpeed = 4e-5;

/// Contacts slower than this are frictionless and have their slips snapped (motion::kSnapSlip):
/// friction there would keep turning spin into approach between wedged balls; with a cushion
/// they are also perfectly inelastic. A ball in more than a few slow contacts at one instant is
/// jammed (simulate.cpp). (unit: m/s)
inline constexpr double kSlowSpeed = 1e-3;

/// The speed that a ball's friction adds toward a contact along `toward` within the contact
/// time (negative: away from it): its acceleration along `toward`, for as long as its segment
/// (its slip) lasts (unit: m/s). A tiny slip pushes only briefly.
double push_speed(const Params& p, const BallState& s, Vec2 toward);

/// The normal speed after a contact (positive: separating), given the approach speed, the
/// push speed (≥ 0, from push_speed: see ball_ball.cpp), the restitution, and whether it is a
/// pushing contact.
double rebound_speed(double approach, double push, double restitution, bool pushing);

/// Ball–ball collision of a and b (touching). Returns the normal approach speed.
/// Models: `frictional` (default; restitution and a friction impulse capped at the end of slip,
/// Alciatore TP A.14 for μ(v)) or `frictionless`. `after_slow`: either ball had a slow contact
/// (kSlowSpeed) within kContactTime before; a slow contact then is chatter (a ball driven or
/// wedged into others), and perfectly inelastic. A slow contact that a real collision brought
/// about (a line of touching balls) keeps its restitution.
double ball_ball(const Params& p, BallBallModel model, BallState& a, BallState& b, bool pushing,
                 bool after_slow = false);

/// Ball–cushion collision. `toward` is the unit horizontal direction from the ball's centre
/// to the cushion (for a straight face, minus its normal; for a jaw nose, toward its axis);
/// `nose_height` the height of the contact above the cloth (unit: m). Returns the normal
/// approach speed.
double cushion(const Params& p, CushionModel model, double nose_height, Vec2 toward, BallState& b,
               bool pushing);

/// Ball–ball friction coefficient for a contact slip speed (unit: m/s).
double ball_ball_friction(const Params& p, double slip_speed);

}  // namespace physics::collide
