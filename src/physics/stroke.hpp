// A cue stroke on the cue ball, as the shooter makes it (docs/cli.md, `strike`).
#pragma once

namespace physics {

struct Stroke {
    double speed = 0.0;        ///< cue stick speed at impact (unit: m/s)
    double heading_deg = 0.0;  ///< horizontal direction of the stroke (unit: deg; 0 = +x, 90 = +y)
    double side = 0.0;         ///< tip offset right of centre as the shooter sees it (unit: R)
    double top = 0.0;          ///< tip offset above centre (unit: R); + is follow, − draw
    double elevation_deg = 0.0;  ///< cue angle above horizontal (unit: deg)
    int ball = 0;  ///< id of the struck ball: 0, or a carom player's own cue ball (1, yellow)
};

}  // namespace physics
