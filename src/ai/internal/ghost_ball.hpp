// Ghost-ball geometry and the analytic chance of a direct pot. The cue ball must arrive where the
// "ghost" ball touches the object ball on the line from the pocket's aim point through the object
// ball; the chance of potting follows from how the stroke's heading error grows on the way
// (a cue-ball offset at contact of d_c·δ turns the object ball by d_c·δ / (2R cos φ)) and how
// wide the pocket looks from the object ball. The physics refines the heading (aim.hpp); this
// model only ranks shots and values positions.
#pragma once

#include <map>
#include <optional>

#include "ai/internal/private.hpp"
#include "physics/params.hpp"
#include "physics/table.hpp"
#include "physics/vec.hpp"

namespace ai {

/// A direct pot: cue ball → ghost ball → object ball → pocket.
struct Aim {
    int ball = 0;
    int pocket = 0;
    physics::Vec2 aim_point;    ///< where the object ball's centre is sent (unit: m)
    physics::Vec2 ghost;        ///< the cue ball's centre at contact (unit: m)
    physics::Vec2 object_dir;   ///< unit direction the object ball must take
    double heading_deg = 0.0;   ///< cue ball → ghost (unit: deg)
    double cut_deg = 0.0;       ///< angle between the cue ball's path and the object's (unit: deg)
    double cue_distance = 0.0;  ///< cue ball to ghost (unit: m)
    double object_distance = 0.0;  ///< object ball to the aim point (unit: m)
    double tolerance = 0.0;  ///< half-angle of the pocket seen from the object ball (unit: rad)
};

/// Effective σ of the cue ball's heading at execution-noise scale 1: the noise model's heading σ
/// combined with the squirt that its side-offset σ causes with this cue (0.125° and 0.169° with
/// the default cue's 15 g end mass: 0.210°) (unit: deg).
double heading_sigma_deg(const physics::Params& params);
/// The least σ the shot model assumes (a noiseless player still prefers easy shots) (unit: deg).
inline constexpr double min_model_sigma_deg = 0.08;

inline constexpr double deg = 3.14159265358979323846 / 180.0;

/// Whether the straight path of a ball's centre from a to b passes at least 2R − slack from
/// every ball of `balls` except `skip1` and `skip2`.
bool path_clear(physics::Vec2 a, physics::Vec2 b, const std::map<int, physics::Vec2>& balls,
                int skip1, int skip2, double radius);

/// The direct pot of `ball` into `pocket` from the cue ball at `cue`; empty when the pocket
/// cannot be reached that way (path blocked, cut over 80°, pocket facing away, ghost ball off
/// the table). `balls` holds the object balls.
std::optional<Aim> direct_aim(const physics::Table& table, double radius, physics::Vec2 cue,
                              int ball, int pocket, const std::map<int, physics::Vec2>& balls);

/// The object ball's path to the pocket alone (for a ball in hand): the aim with no cue ball yet.
std::optional<Aim> object_path(const physics::Table& table, double radius, int ball, int pocket,
                               const std::map<int, physics::Vec2>& balls);

/// The chance of potting `aim` with an execution heading σ of `sigma_deg`.
double aim_chance(const Aim& aim, double radius, double sigma_deg);

/// A combination: the cue ball sends `first` into `second`, which goes on into the pocket.
struct Combination {
    Aim first;   ///< cue ball → `first`, sent to where it meets `second` (`second.ghost`);
                 ///< its tolerance is that of `second` seen back along `first`'s path
    Aim second;  ///< `second` → pocket (its `object_path`)
};

/// The combination's object balls alone (for a ball in hand): `first` to where it meets
/// `second`, `second` to the pocket; the cue ball's part of `first` not set yet.
std::optional<Combination> combination_path(const physics::Table& table, double radius, int first,
                                            int second, int pocket,
                                            const std::map<int, physics::Vec2>& balls);

/// The combination of `first` into `second` into `pocket` from the cue ball at `cue`; empty
/// when a path is blocked, `first` would cut `second` by more than 45° or be cut by more than
/// 70°, or a ghost ball is off the table or taken.
std::optional<Combination> combination_aim(const physics::Table& table, double radius,
                                           physics::Vec2 cue, int first, int second, int pocket,
                                           const std::map<int, physics::Vec2>& balls);

/// The chance of potting `second` by the combination `c` with a heading σ of `sigma_deg`: the
/// heading error grows at each contact as in `aim_chance`.
double combination_chance(const Combination& c, double radius, double sigma_deg);

}  // namespace ai
