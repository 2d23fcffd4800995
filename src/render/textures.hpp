// Procedural textures made at start-up (no image assets): the cloth's fine nap and the
// rails' wood grain. Pure functions returning pixels, so they can be tested without GL.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace render {

struct TextureData {
    int width = 0;
    int height = 0;
    int channels = 1;
    std::vector<std::uint8_t> pixels;  ///< rows bottom to top, `channels` bytes a pixel
};

/// Tileable cloth brightness (one channel, mean about 128): fibre noise with a nap along u.
TextureData make_cloth_texture(int size = 256);
/// Tileable-along-u wood (RGB): rings of a quarter-sawn rail, grain along u.
TextureData make_wood_texture(int width = 1024, int height = 128);

/// The font the ball numbers are rasterized from (Debian package fonts-dejavu-core).
inline constexpr const char* kDefaultNumberFont =
    "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";

/// The ball numbers' atlas (one channel, ink coverage 0–255): kNumberCells × kNumberCells
/// square cells of `cell` pixels, cell i (i = 1..15, row-major from the top-left) holds the
/// number i centred, upright, rows bottom to top like the other textures (so v = 1 is the
/// top of the digits); 6 and 9 are underlined. Cell 0 stays empty. Rasterized with
/// stb_truetype from the TrueType font at `font_path`; throws std::runtime_error naming the
/// file and the package when it cannot be read or parsed.
inline constexpr int kNumberCells = 4;
TextureData make_number_atlas(const std::string& font_path = kDefaultNumberFont, int cell = 64);

}  // namespace render
