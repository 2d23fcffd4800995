#include "app/imgui_setup.hpp"

#include <imgui.h>

#include <filesystem>

namespace app {

void create_imgui() {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // the panel's layout is fixed; nothing to remember
    ImGui::StyleColorsDark();
    ImGuiStyle& st = ImGui::GetStyle();
    st.WindowRounding = 0.0f;
    st.FrameRounding = 4.0f;
    st.GrabRounding = 4.0f;
    st.ItemSpacing = ImVec2(8, 7);
    st.FramePadding = ImVec2(8, 5);
    st.Colors[ImGuiCol_WindowBg] = ImVec4(0.09f, 0.08f, 0.07f, 1.0f);
    st.Colors[ImGuiCol_Button] = ImVec4(0.20f, 0.33f, 0.22f, 1.0f);
    st.Colors[ImGuiCol_ButtonHovered] = ImVec4(0.27f, 0.45f, 0.30f, 1.0f);
    st.Colors[ImGuiCol_ButtonActive] = ImVec4(0.33f, 0.55f, 0.36f, 1.0f);
    st.Colors[ImGuiCol_FrameBg] = ImVec4(0.18f, 0.17f, 0.15f, 1.0f);
    st.Colors[ImGuiCol_SliderGrab] = ImVec4(0.85f, 0.70f, 0.30f, 1.0f);
    st.Colors[ImGuiCol_CheckMark] = ImVec4(0.95f, 0.80f, 0.35f, 1.0f);
    const char* font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    std::error_code ec;
    if (std::filesystem::exists(font, ec)) io.Fonts->AddFontFromFileTTF(font, 15.0f);
}

void destroy_imgui() {
    ImGui::DestroyContext();
}

}  // namespace app
