// How big the side panel is for a window: its width and the scale of its text and widgets, so
// that the table keeps most of a small window and the panel reads well on a large or HiDPI one.
#pragma once

namespace app {

struct PanelLayout {
    float width = 300.0f;  ///< the panel's width (unit: px)
    float scale = 1.0f;    ///< text and widgets, 1 = the 15 px font of a 1280×720 window
};

/// The panel for a `width` × `height` window (unit: px) on a display whose pixels are
/// `dpi_scale` times those of a 96 dpi one: 300 px and scale 1 at 1280×720, growing and
/// shrinking with the window (scale 0.75 to 1.5, times `dpi_scale`), never wider than 40 % of it.
PanelLayout panel_layout(int width, int height, float dpi_scale = 1.0f);

/// The display's scale: $COOLAABER_UI_SCALE when it is a number from 0.5 to 4, else the
/// display's dots per inch / 96 (`dpi`, 0 when unknown) rounded to a quarter, from 1 to 3.
float dpi_scale(const char* ui_scale_variable, float dpi);

}  // namespace app
