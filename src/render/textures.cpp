#include "render/textures.hpp"

#include <algorithm>
#include <cmath>

namespace render {

namespace {

std::uint32_t hash(std::uint32_t x, std::uint32_t y, std::uint32_t seed) {
    std::uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return h;
}

float rand01(int x, int y, std::uint32_t seed) {
    return static_cast<float>(hash(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), seed) & 0xffffu) / 65535.0f;
}

/// Smooth value noise on a lattice of `cells` cells per period (tileable).
float value_noise(float u, float v, int cells_u, int cells_v, std::uint32_t seed) {
    const float x = u * static_cast<float>(cells_u), y = v * static_cast<float>(cells_v);
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
    auto at = [&](int i, int j) {
        return rand01(((i % cells_u) + cells_u) % cells_u, ((j % cells_v) + cells_v) % cells_v, seed);
    };
    const float sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
    const float a = at(x0, y0) + (at(x0 + 1, y0) - at(x0, y0)) * sx;
    const float b = at(x0, y0 + 1) + (at(x0 + 1, y0 + 1) - at(x0, y0 + 1)) * sx;
    return a + (b - a) * sy;
}

std::uint8_t to_byte(float v) { return static_cast<std::uint8_t>(std::clamp(v, 0.0f, 255.0f)); }

}  // namespace

TextureData make_cloth_texture(int size) {
    TextureData t{size, size, 1, std::vector<std::uint8_t>(static_cast<std::size_t>(size) * size)};
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const float u = static_cast<float>(x) / static_cast<float>(size);
            const float v = static_cast<float>(y) / static_cast<float>(size);
            // Fibres: short streaks along u (the nap), plus a little weave and mottling.
            const float fibre = value_noise(u, v, size / 8, size, 1) - 0.5f;
            const float grain = rand01(x, y, 2) - 0.5f;
            const float mottle = value_noise(u, v, 4, 4, 3) + 0.5f * value_noise(u, v, 16, 16, 4) - 0.75f;
            const float weave = ((x + y) % 2 == 0 ? 1.0f : -1.0f);
            t.pixels[static_cast<std::size_t>(y) * size + x] =
                to_byte(128.0f + 34.0f * fibre + 14.0f * grain + 22.0f * mottle + 4.0f * weave);
        }
    return t;
}

TextureData make_wood_texture(int width, int height) {
    TextureData t{width, height, 3, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 3)};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float u = static_cast<float>(x) / static_cast<float>(width);
            const float v = static_cast<float>(y) / static_cast<float>(height);
            // Rings: a distorted distance across the board; long flowing lines along u.
            const float warp = 1.6f * value_noise(u, v, 6, 2, 11) + 0.5f * value_noise(u, v, 24, 4, 12);
            const float rings = 7.0f * v + 0.45f * warp;
            const float ring = std::pow(0.5f + 0.5f * std::sin(rings * 6.2831853f), 3.0f);
            const float fleck = value_noise(u, v, 256, 48, 13) - 0.5f;
            const float dark = std::clamp(0.35f * ring + 0.2f * fleck + 0.15f + 0.1f * value_noise(u, v, 3, 1, 14), 0.0f, 1.0f);
            // Mahogany: from a warm red-brown to a deep brown.
            const float light[3] = {96.0f, 44.0f, 22.0f}, deep[3] = {52.0f, 20.0f, 9.0f};
            for (int c = 0; c < 3; ++c)
                t.pixels[(static_cast<std::size_t>(y) * width + x) * 3 + c] =
                    to_byte(light[c] + (deep[c] - light[c]) * dark);
        }
    return t;
}

}  // namespace render
