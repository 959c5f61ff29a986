#pragma once

#include <imgui.h>

namespace abalike::app
{

/// The editor's panels: placed by the editor every frame, never taking focus by appearing (keys stay with the scene).
inline constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                                ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoFocusOnAppearing |
                                                ImGuiWindowFlags_NoSavedSettings;

/// A section heading (ImGui 1.86 has no SeparatorText).
inline void heading(const char* text)
{
    ImGui::Spacing();
    ImGui::TextDisabled("%s", text);
    ImGui::Separator();
}

} // namespace abalike::app
