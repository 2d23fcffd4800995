#include "render/image.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdlib>

#include "stb_image.h"
#include "stb_image_write.h"

namespace render {

Image read_pixels(int width, int height) {
    Image img{width, height,
              std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4)};
    std::vector<std::uint8_t> raw(img.rgba.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, raw.data());
    const std::size_t row = static_cast<std::size_t>(width) * 4;
    for (int y = 0; y < height; ++y)
        std::copy_n(raw.data() + static_cast<std::size_t>(height - 1 - y) * row, row,
                    img.rgba.data() + static_cast<std::size_t>(y) * row);
    return img;
}

bool write_png(const std::string& path, const Image& image) {
    return stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(),
                          image.width * 4) != 0;
}

Image load_png(const std::string& path) {
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
    if (!data) return {};
    Image img{w, h, std::vector<std::uint8_t>(data, data + static_cast<std::size_t>(w) * h * 4)};
    stbi_image_free(data);
    return img;
}

ImageDiff compare(const Image& a, const Image& b, int tolerance) {
    ImageDiff d;
    d.same_size = a.width == b.width && a.height == b.height && a.rgba.size() == b.rgba.size();
    if (!d.same_size || a.rgba.empty()) return d;
    std::size_t over = 0;
    for (std::size_t p = 0; p < a.rgba.size(); p += 4) {
        int worst = 0;
        for (std::size_t c = 0; c < 4; ++c)
            worst = std::max(worst, std::abs(int(a.rgba[p + c]) - int(b.rgba[p + c])));
        d.max_channel_diff = std::max(d.max_channel_diff, worst);
        if (worst > tolerance) ++over;
    }
    d.fraction_over = static_cast<double>(over) / static_cast<double>(a.rgba.size() / 4);
    return d;
}

}  // namespace render
