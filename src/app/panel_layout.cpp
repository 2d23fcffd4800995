#include "app/panel_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace app {

PanelLayout panel_layout(int width, int height, float dpi_scale) {
    const float w = static_cast<float>(std::max(width, 1));
    const float h = static_cast<float>(std::max(height, 1));
    const float fit = std::clamp(std::min(w / 1280.0f, h / 720.0f), 0.75f, 1.5f);
    PanelLayout p;
    p.scale = fit * std::clamp(dpi_scale, 0.5f, 4.0f);
    p.width = std::round(std::min(300.0f * p.scale, 0.4f * w));
    // A panel squeezed below its natural width shrinks its text with it.
    p.scale = std::min(p.scale, p.width / 300.0f * 1.1f);
    return p;
}

float dpi_scale(const char* ui_scale_variable, float dpi) {
    if (ui_scale_variable && *ui_scale_variable) {
        char* end = nullptr;
        const float v = std::strtof(ui_scale_variable, &end);
        if (end && *end == '\0' && v >= 0.5f && v <= 4.0f) return v;
    }
    if (!(dpi > 0.0f)) return 1.0f;
    return std::clamp(std::round(dpi / 96.0f * 4.0f) / 4.0f, 1.0f, 3.0f);
}

}  // namespace app
