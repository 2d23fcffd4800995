// The offscreen screenshot (--screenshot FILE): the first frame drawn through EGL, no window or
// display needed. Desktop only (the web build has no EGL).
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "app/app.hpp"
#include "app/game_setup.hpp"
#include "app/imgui_setup.hpp"
#include "app/painter.hpp"
#include "app/panel_layout.hpp"
#include "app/scene_frame.hpp"
#include "app/table.hpp"
#include "render/headless_context.hpp"
#include "render/image.hpp"

namespace app {

int run_screenshot(const AppOptions& options) {
    std::optional<GameSetup> setup = set_up_or_report(options);
    if (!setup) return 2;
    try {
        render::HeadlessContext context;
        const int w = setup->settings.window_width, h = setup->settings.window_height;
        Table t(std::move(*setup));
        create_imgui();
        ImGui_ImplOpenGL3_Init("#version 330 core");
        // The backend's GL objects first, as in the window's loop: made after the painter's,
        // the panel came out empty.
        ImGui_ImplOpenGL3_NewFrame();
        Painter painter(t.controller.session().table(),
                        t.controller.session().config().params.ball_radius, t.controller.look());
        const PanelLayout layout =
            panel_layout(w, h, dpi_scale(std::getenv("COOLAABER_UI_SCALE"), 0.0f));
        painter.resize(w, h, table_view(layout, w, h));
        set_ui_scale(layout.scale);
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(static_cast<float>(w), static_cast<float>(h));
        io.DeltaTime = 1.0f / 60.0f;
        t.follow_cue_ball();
        for (int frame = 0; frame < 2; ++frame) {  // ImGui lays its windows out on the first frame
            ImGui_ImplOpenGL3_NewFrame();
            ImGui::NewFrame();
            (void)draw_panel(t.controller, t.setup.settings, t.panel, static_cast<float>(w),
                             static_cast<float>(h), layout);
            ImGui::Render();
        }
        const float aspect =
            static_cast<float>(painter.view_width()) / static_cast<float>(painter.view_height());
        t.rig.update(10.0);
        t.last_camera = t.camera(aspect);
        painter.draw_table(build_scene(t.controller, t.setup.settings.aim_guide), t.last_camera);
        if (!render::write_png(options.screenshot->string(), painter.capture(ImGui::GetDrawData())))
            throw std::runtime_error("cannot write " + options.screenshot->string());
        ImGui_ImplOpenGL3_Shutdown();
        destroy_imgui();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "coolaaber: --screenshot: %s\n", e.what());
        return 1;
    }
    return 0;
}

}  // namespace app
