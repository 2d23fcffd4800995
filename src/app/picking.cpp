#include "app/picking.hpp"

#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>

namespace app {

std::optional<physics::Vec2> table_point(const render::Camera& camera, int width, int height,
                                         double x, double y, double z) {
    if (width <= 0 || height <= 0) return std::nullopt;
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const glm::mat4 inv = glm::inverse(camera.projection(aspect) * camera.view());
    const float nx = static_cast<float>(2.0 * x / width - 1.0);
    const float ny = static_cast<float>(1.0 - 2.0 * y / height);
    glm::vec4 a = inv * glm::vec4(nx, ny, -1.0f, 1.0f);
    glm::vec4 b = inv * glm::vec4(nx, ny, 1.0f, 1.0f);
    a /= a.w;
    b /= b.w;
    const glm::vec3 d = glm::vec3(b) - glm::vec3(a);
    if (std::fabs(d.z) < 1e-9f) return std::nullopt;
    const float t = (static_cast<float>(z) - a.z) / d.z;
    if (t < 0.0f) return std::nullopt;
    const glm::vec3 p = glm::vec3(a) + t * d;
    return physics::Vec2{p.x, p.y};
}

std::optional<std::array<double, 2>> screen_point(const render::Camera& camera, int width,
                                                  int height, physics::Vec2 p, double z) {
    if (width <= 0 || height <= 0) return std::nullopt;
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const glm::vec4 clip =
        camera.projection(aspect) * camera.view() *
        glm::vec4(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(z), 1.0f);
    if (clip.w <= 0.0f) return std::nullopt;
    return std::array<double, 2>{(clip.x / clip.w + 1.0) * width / 2.0,
                                 (1.0 - clip.y / clip.w) * height / 2.0};
}

}  // namespace app
