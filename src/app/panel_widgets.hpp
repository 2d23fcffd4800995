// The panel's small widget helpers, shared by panel.cpp and panel_match.cpp: buttons that
// remember where they were drawn (the status file's test hook) and lengths scaled with the text.
#pragma once

#include <imgui.h>

#include <string>
#include <utility>

#include "app/panel.hpp"

namespace app {

inline const ImVec4 panel_accent{0.95f, 0.80f, 0.35f, 1.0f};
inline const ImVec4 panel_warning{1.0f, 0.45f, 0.40f, 1.0f};

/// Remembers where the last widget was drawn, under `label`.
inline void remember(PanelState& st, const std::string& label) {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    st.widgets[label] = {a.x, a.y, b.x, b.y};
}

inline bool full_button(PanelState& st, const char* label) {
    const bool pressed = ImGui::Button(label, ImVec2(-1.0f, 0.0f));
    remember(st, label);
    return pressed;
}

/// Two buttons side by side, each half the row.
inline std::pair<bool, bool> button_pair(PanelState& st, const char* a, const char* b) {
    const float w = (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x) / 2;
    const bool pa = ImGui::Button(a, ImVec2(w, 0.0f));
    remember(st, a);
    ImGui::SameLine();
    const bool pb = ImGui::Button(b, ImVec2(w, 0.0f));
    remember(st, b);
    return {pa, pb};
}

/// A length of the panel at scale 1, scaled with the text (panel_layout.hpp).
inline float px(float v) {
    return v * ImGui::GetFontSize() / 15.0f;
}

}  // namespace app
