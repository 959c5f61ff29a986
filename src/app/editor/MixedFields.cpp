#include "editor/MixedFields.hpp"

#include <cstdlib>
#include <imgui.h>
#include <imgui_stdlib.h>
#include <map>

namespace abalike::app
{

bool mixedNumberField(const char* label, const std::optional<double>& shared, double& value, bool& released,
                      const char* format)
{
    if (shared)
    {
        value = *shared;
        const bool changed = ImGui::InputDouble(label, &value, 0.0, 0.0, format);
        released |= ImGui::IsItemDeactivated();
        return changed;
    }
    // What is typed into a mixed field, kept by the field's id until it is confirmed.
    static std::map<ImGuiID, std::string> typed;
    std::string& text = typed[ImGui::GetID(label)];
    ImGui::InputTextWithHint(label, "mixed", &text, ImGuiInputTextFlags_CharsScientific);
    if (!ImGui::IsItemDeactivatedAfterEdit())
        return false;
    released = true;
    char* end = nullptr;
    const double number = std::strtod(text.c_str(), &end);
    const bool whole = !text.empty() && end != nullptr && *end == '\0';
    text.clear();
    if (!whole)
        return false;
    value = number;
    return true;
}

bool mixedNameCombo(const char* label, const std::optional<std::string>& shared, const std::vector<std::string>& names,
                    std::string& name)
{
    bool picked = false;
    if (ImGui::BeginCombo(label, shared ? shared->c_str() : "mixed"))
    {
        for (const std::string& option : names)
            if (ImGui::Selectable(option.c_str(), shared && *shared == option) && (!shared || *shared != option))
            {
                name = option;
                picked = true;
            }
        ImGui::EndCombo();
    }
    return picked;
}

} // namespace abalike::app
