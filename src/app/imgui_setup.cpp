#include "app/imgui_setup.hpp"

#include <imgui.h>

#include <filesystem>

namespace app {

namespace {

constexpr float font_size = 15.0f;         // (unit: px) at scale 1
constexpr float font_oversampling = 2.0f;  // the atlas is drawn this much larger: crisp when scaled

// The game's style at scale 1.
ImGuiStyle base_style() {
    ImGuiStyle st;
    ImGui::StyleColorsDark(&st);
    st.WindowRounding = 0.0f;
    st.FrameRounding = 4.0f;
    st.GrabRounding = 4.0f;
    st.ItemSpacing = ImVec2(8, 7);
    st.FramePadding = ImVec2(8, 5);
    st.Colors[ImGuiCol_WindowBg] = ImVec4(0.09f, 0.08f, 0.07f, 1.0f);
    st.Colors[ImGuiCol_ChildBg] = ImVec4(0.0f, 0.0f, 0.0f, 0.0f);
    st.Colors[ImGuiCol_Button] = ImVec4(0.20f, 0.33f, 0.22f, 1.0f);
    st.Colors[ImGuiCol_ButtonHovered] = ImVec4(0.27f, 0.45f, 0.30f, 1.0f);
    st.Colors[ImGuiCol_ButtonActive] = ImVec4(0.33f, 0.55f, 0.36f, 1.0f);
    st.Colors[ImGuiCol_FrameBg] = ImVec4(0.18f, 0.17f, 0.15f, 1.0f);
    st.Colors[ImGuiCol_SliderGrab] = ImVec4(0.85f, 0.70f, 0.30f, 1.0f);
    st.Colors[ImGuiCol_CheckMark] = ImVec4(0.95f, 0.80f, 0.35f, 1.0f);
    return st;
}

// The font atlas's size over font_size (1 for ImGui's built-in font).
float atlas_scale() {
    const ImFontAtlas* fonts = ImGui::GetIO().Fonts;
    return fonts->Fonts.empty() ? 1.0f : fonts->Fonts[0]->FontSize / font_size;
}

}  // namespace

void create_imgui() {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // the panel's layout is fixed; nothing to remember
    const char* font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    std::error_code ec;
    // Latin-1 and the dashes the game's sentences use ("Foul: 4 points to Bob — ...", "3–2").
    static const ImWchar glyphs[] = {0x0020, 0x00FF, 0x2013, 0x2014, 0};
    if (std::filesystem::exists(font, ec))
        io.Fonts->AddFontFromFileTTF(font, font_size * font_oversampling, nullptr, glyphs);
    ImGui::GetStyle() = base_style();
    io.FontGlobalScale = 1.0f / atlas_scale();
}

void set_ui_scale(float scale) {
    ImGuiIO& io = ImGui::GetIO();
    if (io.FontGlobalScale == scale / atlas_scale()) return;
    ImGuiStyle st = base_style();
    st.ScaleAllSizes(scale);
    ImGui::GetStyle() = st;
    io.FontGlobalScale = scale / atlas_scale();
}

void destroy_imgui() {
    ImGui::DestroyContext();
}

}  // namespace app
