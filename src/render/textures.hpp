// Procedural textures made at start-up (no image assets): the cloth's fine nap and the
// rails' wood grain. Pure functions returning pixels, so they can be tested without GL.
#pragma once

#include <cstdint>
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

}  // namespace render
