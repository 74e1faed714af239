#include "explore/widgets.h"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace m3055::explore {

bool slider_double(const char* label, double* value, double lo, double hi, const char* format,
                   bool logarithmic) {
    ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp;
    if (logarithmic) flags |= ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_NoRoundToFormat;
    const bool changed = ImGui::SliderScalar(label, ImGuiDataType_Double, value, &lo, &hi, format, flags);
    *value = std::clamp(*value, lo, hi);
    return changed;
}

bool color_edit(const char* label, dvec3* color) {
    float rgb[3] = {static_cast<float>(color->r), static_cast<float>(color->g),
                    static_cast<float>(color->b)};
    if (!ImGui::ColorEdit3(label, rgb, ImGuiColorEditFlags_Float)) return false;
    for (int i = 0; i < 3; ++i) (*color)[i] = std::clamp(static_cast<double>(rgb[i]), 0.0, 1.0);
    return true;
}

bool lobe_editor(const char* id, std::vector<Lobe>* lobes, const LobeForm& form, int min_lobes) {
    bool changed = false;
    const std::string value_format = form.key + (form.key == "n" ? " %.1f" : " %.3f");
    ImGui::PushID(id);
    for (int j = 0; j < static_cast<int>(lobes->size()); ++j) {
        ImGui::PushID(j);
        Lobe& lobe = (*lobes)[j];
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.36f);
        changed |= slider_double("##w", &lobe.w, form.weight.lo, form.weight.hi, "w %.4f", true);
        ImGui::SameLine();
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.62f);
        changed |= slider_double("##value", &lobe.m, form.value.lo, form.value.hi, value_format.c_str(), true);
        if (ImGui::IsItemHovered() && !form.value_help.empty())
            ImGui::SetTooltip("%s, %s", form.value_help.c_str(), form.value.text().c_str());
        ImGui::SameLine();
        if (static_cast<int>(lobes->size()) > min_lobes && ImGui::SmallButton("x")) {
            lobes->erase(lobes->begin() + j);
            changed = true;
            ImGui::PopID();
            break;
        }
        ImGui::PopID();
    }
    if (static_cast<int>(lobes->size()) < kMaxLobes && ImGui::SmallButton("+ lobe")) {
        lobes->push_back(form.fallback.back());
        changed = true;
    }
    ImGui::PopID();
    return changed;
}

void tooltip(const std::string& text) {
    if (text.empty() || !ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) return;
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

void hint(const char* text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("%s", text);
    ImGui::PopStyleColor();
}

}  // namespace m3055::explore
