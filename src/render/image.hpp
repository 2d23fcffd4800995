// RGBA8 images read back from GL, written as PNG (stb_image_write), compared with tolerance.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace render {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  ///< rows top to bottom, 4 bytes a pixel
};

/// Reads the current read framebuffer (rows flipped so the top row comes first).
Image read_pixels(int width, int height);
/// Writes a PNG; false on failure.
bool write_png(const std::string& path, const Image& image);
/// Loads a PNG as RGBA8; empty image (width 0) on failure.
Image load_png(const std::string& path);

struct ImageDiff {
    int max_channel_diff = 0;  ///< largest |a − b| over all channels (unit: 1/255)
    double fraction_over =
        0.0;  ///< fraction of pixels with a channel differing by more than the tolerance
    bool same_size = false;
};
ImageDiff compare(const Image& a, const Image& b, int tolerance);

}  // namespace render
