#include "explore_ui/widgets.h"

#include "explore/slider_scale.h"
#include "explore_ui/narrow_panel.h"

#include <imgui.h>
#include <imgui_internal.h>  // ItemAdd, ImGuiItemFlags_Inputable: Tab reaches the logarithmic sliders (1.86)
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>

namespace m3055::explore {

namespace {

// "w %.4f" -> {"w ", ""}: the text around the printf conversion of a format.
std::pair<std::string, std::string> around_conversion(const std::string& format) {
    const auto percent = format.find('%');
    if (percent == std::string::npos) return {format, ""};
    const auto conversion = format.find_first_of("fFeEgGd", percent);
    if (conversion == std::string::npos) return {format.substr(0, percent), ""};
    return {format.substr(0, percent), format.substr(conversion + 1)};
}

// ImGui shows a format without a conversion as plain text; a '%' in it must be doubled.
std::string literal_format(const std::string& text) {
    std::string out;
    for (char c : text) out += c == '%' ? std::string("%%") : std::string(1, c);
    return out;
}

// Ctrl+click on a logarithmic slider, or Tab reaching it, types the value
// itself (not the slider's position): the item being typed into, if any.
ImGuiID typing_id = 0;
bool typing_focus = false;  // give the field the keyboard in its first frame

// The field being typed into (typed_field): its text lives here while it is active.
ImGuiID editing_id = 0;
std::string editing_text;

// The slider just drawn takes part in Tab's order: it is NoInput (ImGui's
// own typing would edit its position), so an item of its own at its place
// receives the focus, and true says Tab has just reached it. The slider stays
// the last item (its hover and tooltip).
bool tab_reached(const char* label) {
    ImGuiContext& g = *ImGui::GetCurrentContext();
    const ImGuiLastItemData slider = g.LastItemData;
    ImGui::PushID(label);
    const ImGuiID tab_id = ImGui::GetID("##tab");
    ImGui::PopID();
    // Tab's request found this item last frame and activates it now (1.86's tabbing is a nav move).
    const bool reached = ImGui::ItemAdd(slider.Rect, tab_id, nullptr, ImGuiItemFlags_Inputable) &&
                         (g.NavActivateInputId == tab_id || g.NavActivateId == tab_id);
    g.LastItemData = slider;
    return reached;
}

// Shift held on a held slider: the slider's last item moves a tenth as fast
// as the mouse from where it was when Shift went down (slider_scale.h's
// fine_drag_position). `position` is the item's position before this frame's
// slider call; set to the fine one. False when no fine drag is on.
ImGuiID fine_id = 0;
double fine_anchor_position = 0.0, fine_anchor_x = 0.0;

bool fine_drag(ImGuiID id, double before, double* position) {
    const ImGuiIO& io = ImGui::GetIO();
    if (!ImGui::IsItemActive() || !io.KeyShift) {
        if (fine_id == id) fine_id = 0;
        return false;
    }
    if (fine_id != id) {
        fine_id = id;
        fine_anchor_position = before;
        fine_anchor_x = io.MousePos.x;
    }
    *position = fine_drag_position(fine_anchor_position, fine_anchor_x, io.MousePos.x, ImGui::GetItemRectSize().x);
    return true;
}

// A slider over the position (slider_scale.h) that shows the value with three
// significant digits; Ctrl+click types the value; Shift drags finely.
bool log_slider(const char* label, double* value, double lo, double hi, const char* format, double decades) {
    const ImGuiID id = ImGui::GetID(label);
    if (typing_id == id) {
        if (typing_focus) ImGui::SetKeyboardFocusHere();
        typing_focus = false;
        char shown[32];
        std::snprintf(shown, sizeof shown, "%.6g", *value);
        const std::string field = std::string(label) + "##typed";  // an ID of its own, the same label
        std::string typed;
        const bool left = typed_field(field.c_str(), shown, &typed);
        if (left || ImGui::IsItemDeactivated()) typing_id = 0;
        char* end = nullptr;
        const double number = std::strtod(typed.c_str(), &end);
        if (!left || end == typed.c_str() || !std::isfinite(number)) return false;
        const double clamped = std::clamp(number, lo, hi);
        if (clamped == *value) return false;
        *value = clamped;
        return true;
    }
    const auto [before, after] = around_conversion(format);
    const std::string shown = literal_format(before + significant_text(*value) + after);
    const double at = log_slider_position(*value, lo, hi, decades);
    float position = static_cast<float>(at);
    bool moved = ImGui::SliderFloat(label, &position, 0.0f, 1.0f, shown.c_str(),
                                    ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_NoInput);
    if (tab_reached(label)) {
        typing_id = id;
        typing_focus = true;
        return false;
    }
    // The value at slider position `p`, as a drag leaves it; false when that is the value already.
    const auto drag_to = [&](double p) {
        const double dragged = dragged_value(log_slider_value(p, lo, hi, decades), lo, hi);
        if (dragged == *value) return false;
        *value = dragged;
        return true;
    };
    double fine = at;
    if (fine_drag(id, at, &fine)) return drag_to(fine);
    if (ImGui::IsItemHovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && ImGui::GetIO().KeyCtrl) {
        typing_id = id;  // and the click does not move the value
        typing_focus = true;
        return false;
    }
    if (!moved) return false;
    return drag_to(position);
}

}  // namespace

bool typed_field(const char* label, const std::string& shown, std::string* typed, bool enter_only) {
    const ImGuiID id = ImGui::GetID(label);
    std::string local = shown;
    std::string& text = editing_id == id ? editing_text : local;
    const bool enter = ImGui::InputText(label, &text, ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
    if (ImGui::IsItemActivated()) {
        editing_id = id;
        editing_text = text;
    }
    if (!ImGui::IsItemDeactivated() || editing_id != id) return false;
    // Left: by Enter, by Tab or a click elsewhere, or by Esc (ImGui has then
    // put the text it started with back: applying it changes nothing).
    editing_id = 0;
    if (enter_only && !enter) return false;
    *typed = std::move(editing_text);
    return true;
}

bool typed_ints(const char* label, int* values, int count, int lo, int hi) {
    bool changed = false;
    ImGui::PushID(label);
    ImGui::BeginGroup();
    const float width = (ImGui::CalcItemWidth() - ImGui::GetStyle().ItemInnerSpacing.x * float(count - 1)) / float(count);
    for (int i = 0; i < count; ++i) {
        ImGui::PushID(i);
        if (i > 0) ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
        ImGui::SetNextItemWidth(width);
        std::string typed;
        if (typed_field("##value", std::to_string(values[i]), &typed)) {
            char* end = nullptr;
            const long number = std::strtol(typed.c_str(), &end, 10);
            if (end != typed.c_str() && std::clamp<long>(number, lo, hi) != values[i]) {
                values[i] = int(std::clamp<long>(number, lo, hi));
                changed = true;
            }
        }
        ImGui::PopID();
    }
    const std::string shown = label;
    const std::size_t hidden = shown.find("##");
    if (hidden != 0) {
        ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
        ImGui::TextUnformatted(shown.substr(0, hidden).c_str());
    }
    ImGui::EndGroup();
    ImGui::PopID();
    return changed;
}

bool slider_double(const char* label, double* value, double lo, double hi, const char* format,
                   bool logarithmic, double decades) {
    const std::string shown = field(label);  // its own line on a narrow panel
    label = shown.c_str();
    if (logarithmic) return log_slider(label, value, lo, hi, format, decades);
    const ImGuiID id = ImGui::GetID(label);
    const double old = *value;
    const double before = hi > lo ? (old - lo) / (hi - lo) : 0.0;
    bool changed = ImGui::SliderScalar(label, ImGuiDataType_Double, value, &lo, &hi, format,
                                       ImGuiSliderFlags_AlwaysClamp);
    double fine = before;
    if (fine_drag(id, before, &fine)) {
        *value = lo + fine * (hi - lo);
        changed = *value != old;
    }
    *value = std::clamp(*value, lo, hi);
    return changed;
}

// The double a person meant by float `f`: its shortest decimal form that reads
// back as `f` (0.1f is 0.1, not 0.10000000149011612 in a saved scene).
static double shortest_double(float f) {
    char text[32];
    for (int digits = 1; digits <= 9; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, double(f));
        if (std::strtof(text, nullptr) == f) break;
    }
    return std::strtod(text, nullptr);
}

bool color_edit(const char* label, dvec3* color) {
    float rgb[3] = {static_cast<float>(color->r), static_cast<float>(color->g),
                    static_cast<float>(color->b)};
    const float before[3] = {rgb[0], rgb[1], rgb[2]};
    if (!ImGui::ColorEdit3(field(label).c_str(), rgb, ImGuiColorEditFlags_Float)) return false;
    // ImGui edits floats: a channel left alone keeps its double exactly.
    for (int i = 0; i < 3; ++i)
        if (rgb[i] != before[i]) (*color)[i] = std::clamp(shortest_double(rgb[i]), 0.0, 1.0);
    return true;
}

bool lobe_editor(const char* id, std::vector<Lobe>* lobes, const LobeForm& form, int min_lobes) {
    bool changed = false;
    const std::string value_format = form.key + (form.key == "n" ? " %.1f" : " %.3f");
    ImGui::PushID(id);
    for (int j = 0; j < static_cast<int>(lobes->size()); ++j) {
        ImGui::PushID(j);
        Lobe& lobe = (*lobes)[j];
        // One row each for w and the value, full width: the weight's seven
        // decades (slider_scale.h) get about 40 px each.
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 40.0f);
        changed |= slider_double("##w", &lobe.w, form.weight.lo, form.weight.hi, "w %.4f", true);
        if (tooltip_due())
            ImGui::SetTooltip("lobe weight w_%d, %s (logarithmic; Ctrl+click to type)", j + 1,
                              form.weight.text().c_str());
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 40.0f);
        changed |= slider_double("##value", &lobe.m, form.value.lo, form.value.hi, value_format.c_str(), true);
        if (tooltip_due() && !form.value_help.empty())
            ImGui::SetTooltip("%s, %s", form.value_help.c_str(), form.value.text().c_str());
        // The remove button only where a lobe may go (else "+ lobe" would
        // join this row, past the panel's edge, cut to "+ lob").
        bool removed = false;
        if (static_cast<int>(lobes->size()) > min_lobes) {
            ImGui::SameLine();
            removed = ImGui::SmallButton("x");
            tooltip("Removes this lobe.");
        }
        if (removed) {
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
    if (static_cast<int>(lobes->size()) < kMaxLobes)
        tooltip("Adds a lobe (at most " + std::to_string(kMaxLobes) + ", spec section 7).");
    ImGui::PopID();
    return changed;
}

bool tooltip_due() { return ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled) && !ImGui::IsItemActive(); }

void tooltip(const std::string& text) {
    if (text.empty() || !tooltip_due()) return;
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
