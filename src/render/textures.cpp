#include "render/textures.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "stb_truetype.h"

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
    return static_cast<float>(
               hash(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), seed) & 0xffffu) /
           65535.0f;
}

/// Smooth value noise on a lattice of `cells` cells per period (tileable).
float value_noise(float u, float v, int cells_u, int cells_v, std::uint32_t seed) {
    const float x = u * static_cast<float>(cells_u), y = v * static_cast<float>(cells_v);
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
    auto at = [&](int i, int j) {
        return rand01(((i % cells_u) + cells_u) % cells_u, ((j % cells_v) + cells_v) % cells_v,
                      seed);
    };
    const float sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
    const float a = at(x0, y0) + (at(x0 + 1, y0) - at(x0, y0)) * sx;
    const float b = at(x0, y0 + 1) + (at(x0 + 1, y0 + 1) - at(x0, y0 + 1)) * sx;
    return a + (b - a) * sy;
}

std::uint8_t to_byte(float v) {
    return static_cast<std::uint8_t>(std::clamp(v, 0.0f, 255.0f));
}

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
            const float mottle =
                value_noise(u, v, 4, 4, 3) + 0.5f * value_noise(u, v, 16, 16, 4) - 0.75f;
            // A 2/2 twill: threads of two texels (about 0.3 mm) crossing on the diagonal.
            const float weave = ((x + y) / 2) % 2 == 0 ? 1.0f : -1.0f;
            const float thread = (x % 2 == 0) ? 0.5f : -0.5f;
            t.pixels[static_cast<std::size_t>(y) * size + x] =
                to_byte(128.0f + 30.0f * fibre + 12.0f * grain + 22.0f * mottle + 10.0f * weave +
                        4.0f * thread);
        }
    return t;
}

TextureData make_wood_texture(int width, int height) {
    TextureData t{width, height, 3,
                  std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 3)};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float u = static_cast<float>(x) / static_cast<float>(width);
            const float v = static_cast<float>(y) / static_cast<float>(height);
            // Rings: a distorted distance across the board; long flowing lines along u.
            const float warp =
                1.6f * value_noise(u, v, 6, 2, 11) + 0.5f * value_noise(u, v, 24, 4, 12);
            const float rings = 7.0f * v + 0.45f * warp;
            const float ring = std::pow(0.5f + 0.5f * std::sin(rings * 6.2831853f), 3.0f);
            const float fleck = value_noise(u, v, 256, 48, 13) - 0.5f;
            const float dark =
                std::clamp(0.35f * ring + 0.2f * fleck + 0.15f + 0.1f * value_noise(u, v, 3, 1, 14),
                           0.0f, 1.0f);
            // Mahogany: from a warm red-brown to a deep brown.
            const float light[3] = {96.0f, 44.0f, 22.0f}, deep[3] = {52.0f, 20.0f, 9.0f};
            for (int c = 0; c < 3; ++c)
                t.pixels[(static_cast<std::size_t>(y) * width + x) * 3 + c] =
                    to_byte(light[c] + (deep[c] - light[c]) * dark);
        }
    return t;
}

namespace {

// A TrueType font file and stb's view of it (which points into the file's bytes).
struct Font {
    std::vector<unsigned char> file;
    stbtt_fontinfo info{};

    explicit Font(const std::string& path) {
        std::ifstream in(path, std::ios::binary);
        file.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        if (file.empty())
            throw std::runtime_error(
                "cannot read the ball-number font " + path +
                " (Debian: apt-get install fonts-dejavu-core; or set RenderSettings::number_font)");
        const int offset = stbtt_GetFontOffsetForIndex(file.data(), 0);
        if (offset < 0 || !stbtt_InitFont(&info, file.data(), offset))
            throw std::runtime_error("the ball-number font " + path + " is not a TrueType font");
    }
    Font(const Font&) = delete;
    Font& operator=(const Font&) = delete;

    // At scale 1: the pen's advance past `c`, and the kerning between `a` and `b`.
    float advance(int c) const {
        int adv = 0, lsb = 0;
        stbtt_GetCodepointHMetrics(&info, c, &adv, &lsb);
        return static_cast<float>(adv);
    }
    float kerning(int a, int b) const {
        return static_cast<float>(stbtt_GetCodepointKernAdvance(&info, a, b));
    }
};

// One cell of the atlas: its top-left pixel (rows top down) and size.
struct Cell {
    int x, y, size;
};

// Draws `codepoint` at (pen, baseline) with scales (sx, sy), clipped to the cell's inside.
void draw_glyph(TextureData& t, const Font& font, int codepoint, float sx, float sy, float pen,
                float baseline, Cell c) {
    int gx0 = 0, gy0 = 0, gx1 = 0, gy1 = 0;
    const float shift = pen - std::floor(pen);
    stbtt_GetCodepointBitmapBoxSubpixel(&font.info, codepoint, sx, sy, shift, 0.0f, &gx0, &gy0,
                                        &gx1, &gy1);
    const int gw = gx1 - gx0, gh = gy1 - gy0;
    if (gw <= 0 || gh <= 0) return;
    std::vector<unsigned char> glyph(static_cast<std::size_t>(gw) * static_cast<std::size_t>(gh),
                                     0);
    stbtt_MakeCodepointBitmapSubpixel(&font.info, glyph.data(), gw, gh, gw, sx, sy, shift, 0.0f,
                                      codepoint);
    const int ox = static_cast<int>(std::floor(pen)) + gx0;
    const int oy = static_cast<int>(std::lround(baseline)) + gy0;
    for (int y = 0; y < gh; ++y)
        for (int x = 0; x < gw; ++x) {
            const int px = ox + x, py = oy + y;
            if (px < c.x + 1 || px >= c.x + c.size - 1 || py < c.y + 1 || py >= c.y + c.size - 1)
                continue;
            std::uint8_t& dst =
                t.pixels[static_cast<std::size_t>(t.height - 1 - py) * t.width + px];
            dst = std::max(dst, glyph[static_cast<std::size_t>(y) * gw + x]);
        }
}

// The underline that tells 6 from 9 on a turned ball.
void underline(TextureData& t, float baseline, Cell c) {
    const int ux0 = c.x + c.size * 36 / 100, ux1 = c.x + c.size * 64 / 100;
    const int uy0 = static_cast<int>(std::lround(baseline)) + c.size * 6 / 100;
    const int uy1 = uy0 + std::max(2, c.size * 7 / 100);
    for (int py = uy0; py < uy1 && py < c.y + c.size - 1; ++py)
        for (int px = ux0; px < ux1; ++px)
            t.pixels[static_cast<std::size_t>(t.height - 1 - py) * t.width + px] = 255;
}

// Ball number n, centred in its cell on the digits' shared baseline (`digit_h`: the height of
// "0" at scale 1).
void draw_number(TextureData& t, const Font& font, int n, Cell c, float digit_h) {
    const std::string text = std::to_string(n);
    const bool two = text.size() > 1;
    // Single digits 0.62 of the cell tall; pairs a little smaller and condensed, as on real
    // balls.
    const float sy = (two ? 0.56f : 0.62f) * static_cast<float>(c.size) / digit_h;
    float sx = sy;
    float width = 0.0f;  // at scale 1, to centre the number (and fit pairs)
    for (std::size_t k = 0; k < text.size(); ++k) {
        width += font.advance(text[k]);
        if (k + 1 < text.size()) width += font.kerning(text[k], text[k + 1]);
    }
    if (two) sx = std::min(sx * 0.86f, 0.80f * static_cast<float>(c.size) / width);
    const float baseline =
        static_cast<float>(c.y) + 0.5f * static_cast<float>(c.size) + 0.5f * digit_h * sy;
    float pen = static_cast<float>(c.x) + 0.5f * static_cast<float>(c.size) - 0.5f * width * sx;
    for (std::size_t k = 0; k < text.size(); ++k) {
        draw_glyph(t, font, text[k], sx, sy, pen, baseline, c);
        pen += font.advance(text[k]) * sx;
        if (k + 1 < text.size()) pen += font.kerning(text[k], text[k + 1]) * sx;
    }
    if (n == 6 || n == 9) underline(t, baseline, c);
}

}  // namespace

TextureData make_number_atlas(const std::string& font_path, int cell) {
    const Font font(font_path);
    const int size = kNumberCells * cell;
    TextureData t{size, size, 1,
                  std::vector<std::uint8_t>(static_cast<std::size_t>(size) * size, 0)};
    // The digits' height: that of "0" in the font, so every number shares one baseline.
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    stbtt_GetCodepointBox(&font.info, '0', &x0, &y0, &x1, &y1);
    const float digit_h = static_cast<float>(y1 - y0);
    for (int n = 1; n <= 15; ++n)
        draw_number(t, font, n, {(n % kNumberCells) * cell, (n / kNumberCells) * cell, cell},
                    digit_h);
    return t;
}

}  // namespace render
