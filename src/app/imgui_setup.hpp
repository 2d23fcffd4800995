// Dear ImGui's context, style and font for the panel (the OpenGL 3 renderer backend; the SDL
// backend is added by the window).
#pragma once

namespace app {

/// Creates the ImGui context with the game's style; loads DejaVu Sans when the font package is
/// installed (fonts-dejavu-core), else ImGui's built-in font.
void create_imgui();
void destroy_imgui();
/// Scales the panel's text and widgets (panel_layout.hpp); cheap when `scale` is unchanged.
void set_ui_scale(float scale);

}  // namespace app
