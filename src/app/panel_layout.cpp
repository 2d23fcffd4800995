#include "app/panel_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace app {

namespace {

// The panel's share of a tall window's height: the table above keeps the rest.
constexpr float below_share = 0.45f;

PanelLayout at_the_right(float w, float h, float dpi_scale) {
    const float fit = std::clamp(std::min(w / 1280.0f, h / 720.0f), 0.75f, 1.5f);
    PanelLayout p;
    p.scale = fit * dpi_scale;
    p.width = std::round(std::min(300.0f * p.scale, 0.4f * w));
    // A panel squeezed below its natural width shrinks its text with it.
    p.scale = std::min(p.scale, p.width / 300.0f * 1.1f);
    return p;
}

// Full width under the table: the text keeps its size, as wide as a 300 px panel's at most
// (a phone 390 CSS px wide, at 1.5 for a finger, gets 1.125: a 17 px font).
PanelLayout below_the_table(float w, float h, float dpi_scale) {
    const float fit = std::clamp(std::min(w / 720.0f, h / 1280.0f), 0.75f, 1.5f);
    PanelLayout p;
    p.place = PanelPlace::below;
    p.width = w;
    p.height = std::round(below_share * h);
    p.scale = std::min(fit * dpi_scale, w / 300.0f * 1.1f);
    return p;
}

}  // namespace

PanelLayout panel_layout(int width, int height, float dpi_scale) {
    const float w = static_cast<float>(std::max(width, 1));
    const float h = static_cast<float>(std::max(height, 1));
    const float dpi = std::clamp(dpi_scale, 0.5f, 4.0f);
    return h > w ? below_the_table(w, h, dpi) : at_the_right(w, h, dpi);
}

ViewSize table_view(const PanelLayout& panel, int width, int height) {
    if (panel.place == PanelPlace::below)
        return {std::max(16, width), std::max(16, height - static_cast<int>(panel.height))};
    return {std::max(16, width - static_cast<int>(panel.width)), std::max(16, height)};
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
