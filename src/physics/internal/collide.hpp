// Collision models: impulses at an instant of contact. Private to physics.
#pragma once

#include "physics/ball_state.hpp"
#include "physics/internal/private.hpp"
#include "physics/params.hpp"

namespace physics::collide {

// Chatter (physics-model.md, trap 3). Friction can keep two touching bodies accelerating into
// each other (a spinning ball driving into another, or into a cushion); an event-based engine
// then sees ever smaller bounces. Two rules keep the events per contact few:
/// Approach speeds below this are perfectly inelastic and frictionless (unit: m/s).
inline constexpr double kInelasticSpeed = 1e-3;
/// Contacts closer together in time than this are one resting contact (unit: s; the gaps it
/// opens stay under 25 µm): a bounce that
/// the contact's own acceleration would bring back within it is perfectly inelastic, and a
/// "pushing" contact (touching, no approach speed, accelerating into contact) is separated just
/// fast enough to return after it, with the energy that takes removed from the balls' motion.
inline constexpr double kContactTime = 0.01;
/// Least separation speed of a pushing contact (unit: m/s); each ball gets half of it, which
/// must stay above motion::kRestSpeed so the separation is not settled away.
inline constexpr double kSeparationSpeed = 4e-5;

/// The speed that a ball's friction adds toward a contact along `toward` within the contact
/// time: its acceleration into the contact, for as long as its segment (its slip) lasts
/// (unit: m/s). A tiny slip pushes only briefly.
double push_speed(const Params& p, const BallState& s, Vec2 toward);

/// The normal speed after a contact (positive: separating), given the approach speed, the
/// push speed (≥ 0, see push_speed), the restitution, and whether it is a pushing contact.
double rebound_speed(double approach, double push, double restitution, bool pushing);

/// Ball–ball collision of a and b (touching). Returns the normal approach speed.
/// Models: `frictional` (default; restitution and a friction impulse capped at the end of slip,
/// Alciatore TP A.14 for μ(v)) or `frictionless`.
double ball_ball(const Params& p, BallBallModel model, BallState& a, BallState& b, bool pushing);

/// Ball–cushion collision. `toward` is the unit horizontal direction from the ball's centre
/// to the cushion (for a straight face, minus its normal; for a jaw nose, toward its axis);
/// `nose_height` the height of the contact above the cloth (unit: m). Returns the normal
/// approach speed.
double cushion(const Params& p, CushionModel model, double nose_height, Vec2 toward, BallState& b,
               bool pushing);

/// Ball–ball friction coefficient for a contact slip speed (unit: m/s).
double ball_ball_friction(const Params& p, double slip_speed);

}  // namespace physics::collide
