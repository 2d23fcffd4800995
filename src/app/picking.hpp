// From a point on the screen to a point on the table: the ray through the pixel meets the
// horizontal plane at a ball's centre height.
#pragma once

#include <array>
#include <optional>

#include "physics/vec.hpp"
#include "render/camera.hpp"

namespace app {

/// Pixel (x, y) of a `width` × `height` view (origin top left) seen through `camera`; the
/// point at height `z` (unit: m) where its ray meets that plane, or empty when it points away.
std::optional<physics::Vec2> table_point(const render::Camera& camera, int width, int height,
                                         double x, double y, double z);

/// The inverse: the pixel (x, y) where the point `p` at height `z` is seen, or empty when it
/// lies behind the camera (the status file's ball pixels, for tests that drag a ball).
std::optional<std::array<double, 2>> screen_point(const render::Camera& camera, int width,
                                                  int height, physics::Vec2 p, double z);

}  // namespace app
