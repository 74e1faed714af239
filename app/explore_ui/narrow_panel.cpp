#include "explore_ui/narrow_panel.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <cfloat>

namespace m3055::explore {

namespace {
bool narrow = false;
}

void set_narrow_panel(bool on) { narrow = on; }
bool narrow_panel() { return narrow; }

std::string field(const char* label) {
    const char* end = ImGui::FindRenderedTextEnd(label);
    if (!narrow || end == label) return label;  // a hidden label keeps the caller's width
    ImGui::TextUnformatted(label, end);
    ImGui::SetNextItemWidth(-FLT_MIN);
    return std::string("##") + label;
}

int combo_flags() { return narrow ? ImGuiComboFlags_NoArrowButton : ImGuiComboFlags_None; }

bool checkbox(const char* label, bool* value) {
    if (!narrow) return ImGui::Checkbox(label, value);
    ImGui::PushID(label);
    const bool changed = ImGui::Checkbox("##box", value);
    ImGui::PopID();
    ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::TextWrapped("%s", std::string(label, ImGui::FindRenderedTextEnd(label)).c_str());
    return changed;
}

void same_line_if_fits(float next_width) {
    // From the last item's edge, as SameLine() would place it (not SameLine()
    // then NewLine(): that counts the spacing as content past the edge).
    const float x = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x;
    const float right = ImGui::GetWindowContentRegionMax().x + ImGui::GetWindowPos().x;
    if (x + next_width <= right) ImGui::SameLine();
}

float button_width(const char* label) {
    // Small buttons differ only in their vertical padding.
    return ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * ImGui::GetStyle().FramePadding.x;
}

}  // namespace m3055::explore
