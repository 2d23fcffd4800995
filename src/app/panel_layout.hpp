// How big the panel is for a window and where it goes: at the right of a wide window, below
// the table in a tall one; its size and the scale of its text and widgets, so that the table
// keeps most of a small window and the panel reads well on a large, HiDPI or phone screen.
#pragma once

namespace app {

/// Where the panel sits: at the right of the table view (a wide window), or under it, full
/// width (a tall window: a phone held upright).
enum class PanelPlace { right, below };

struct PanelLayout {
    PanelPlace place = PanelPlace::right;
    float width = 300.0f;  ///< the panel's width (unit: px)
    float height = 0.0f;   ///< below the table: the panel's height (unit: px); at the right: 0
    float scale = 1.0f;    ///< text and widgets, 1 = the 15 px font of a 1280×720 window
};

/// The table view's size: the window less the panel (unit: px; its origin is the window's
/// top left corner in both places).
struct ViewSize {
    int width = 0;
    int height = 0;
};

/// The panel for a `width` × `height` window (unit: px) on a display whose pixels are
/// `dpi_scale` times those of a 96 dpi one. A wide window (width ≥ height): at the right,
/// 300 px and scale 1 at 1280×720, growing and shrinking with the window (scale 0.75 to 1.5,
/// times `dpi_scale`), never wider than 40 % of it. A tall one: below the table, the window's
/// width and 45 % of its height, scaled as a 720×1280 window's and never wider than it fits.
PanelLayout panel_layout(int width, int height, float dpi_scale = 1.0f);

/// What the table view keeps of a `width` × `height` window beside or above `panel`.
ViewSize table_view(const PanelLayout& panel, int width, int height);

/// The display's scale: $COOLAABER_UI_SCALE when it is a number from 0.5 to 4, else the
/// display's dots per inch / 96 (`dpi`, 0 when unknown) rounded to a quarter, from 1 to 3.
float dpi_scale(const char* ui_scale_variable, float dpi);

}  // namespace app
