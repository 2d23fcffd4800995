// The aim guide as each level shows it (docs/app.md, "Aim guide"), and the marks of the call on
// the cloth: read off the simulated preview (aim_preview.hpp), nothing simulated here.
#pragma once

#include "app/aim_preview.hpp"
#include "app/settings.hpp"
#include "physics/table.hpp"
#include "render/renderer.hpp"
#include "rules/game_state.hpp"

namespace app {

/// Lengths of the `lines` level's short lines (unit: m).
inline constexpr float object_line_length = 0.25f;
inline constexpr float tangent_line_length = 0.12f;

/// The guide for `preview` at `level` (`illegal`: drawn red). Off gives an empty view.
render::AimView guide_view(const AimPreview& preview, AimGuide level, bool illegal, float R);

/// Adds the called ball's ring (at `ball_at`) and the called pocket's ring.
void add_call_marks(render::AimView& view, const physics::Table& table, physics::Vec2 ball_at,
                    int pocket, float R);

/// Adds a red ring round the ball at `ball_at`: the shot as aimed is a foul on it.
void add_foul_mark(render::AimView& view, physics::Vec2 ball_at, float R);

}  // namespace app
