// Spectra section (docs/spec.md#74-the-spectra-in-use): the spectrum of the
// selected light as the renderer normalizes it (luminance 1; E = 1) and the
// selected material's reflectance R(lambda), over 380-780 nm. The numbers are
// scene/spectrum_view.h's, the same as `m3055 plot spectrum` draws.
#include "explore_ui/panels.h"

#include "explore_ui/narrow_panel.h"
#include "explore_ui/widgets.h"
#include "scene/spectrum_view.h"
#include "spectral/spectrum.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace m3055::explore {

namespace {

constexpr ImU32 kLightColour = IM_COL32(235, 160, 40, 255);  // as the gnuplot's light curve
constexpr ImU32 kReflectanceColour = IM_COL32(110, 150, 255, 255);

std::string light_entry(const std::vector<Light>& lights, int i) {
    const Light& light = lights[std::size_t(i)];
    return "light " + std::to_string(i) + (light.name.empty() ? "" : " \"" + light.name + "\"");
}

// The curves: the light scaled to the plot's top (its largest value, at least
// 1), R on [0, 1]; grid lines every 100 nm; the values under the mouse in a tooltip.
void spectra_plot(const SpectrumView& view, float width, float height) {
    const auto& c = view.curves;
    const double top = std::max(1.0, *std::max_element(c.light.begin(), c.light.end()));
    ImGui::TextDisabled("top: S %.2f, R 1; nm below", top);
    const ImVec2 lo = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##spectra", ImVec2(width, height));
    const bool hovered = ImGui::IsItemHovered();
    const float label_h = ImGui::GetTextLineHeight();
    const ImVec2 hi(lo.x + width, lo.y + height - label_h);  // the wavelengths under the plot
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRect(lo, hi, IM_COL32(255, 255, 255, 40));
    const auto x_of = [&](double nm) {
        return lo.x + float((nm - c.nm.front()) / (c.nm.back() - c.nm.front())) * (hi.x - lo.x);
    };
    for (int nm = 400; nm <= 700; nm += 100) {
        const float x = x_of(nm);
        draw->AddLine(ImVec2(x, lo.y), ImVec2(x, hi.y), IM_COL32(255, 255, 255, 28));
        char text[8];
        std::snprintf(text, sizeof text, "%d", nm);
        draw->AddText(ImVec2(std::max(lo.x, x - ImGui::CalcTextSize(text).x * 0.5f), hi.y), IM_COL32(255, 255, 255, 140), text);
    }
    const auto polyline = [&](const std::vector<double>& values, double scale, ImU32 colour) {
        std::vector<ImVec2> points;
        for (std::size_t i = 0; i < values.size(); ++i)
            points.emplace_back(x_of(c.nm[i]), hi.y - float(std::clamp(values[i] / scale, 0.0, 1.0)) * (hi.y - lo.y));
        draw->AddPolyline(points.data(), static_cast<int>(points.size()), colour, 0, 1.5f);
    };
    polyline(c.light, top, kLightColour);
    if (!c.reflectance.empty()) polyline(c.reflectance, 1.0, kReflectanceColour);
    if (!hovered) return;
    const float mouse = ImGui::GetIO().MousePos.x;
    const std::size_t i = std::size_t(std::lround(std::clamp((mouse - lo.x) / (hi.x - lo.x), 0.0f, 1.0f) *
                                                  float(c.nm.size() - 1)));
    draw->AddLine(ImVec2(x_of(c.nm[i]), lo.y), ImVec2(x_of(c.nm[i]), hi.y), IM_COL32(255, 255, 255, 90));
    if (c.reflectance.empty()) ImGui::SetTooltip("%.0f nm: S %.3f", c.nm[i], c.light[i]);
    else ImGui::SetTooltip("%.0f nm: S %.3f, R %.3f", c.nm[i], c.light[i], c.reflectance[i]);
}

// A short coloured line and its text, wrapping.
void legend(ImU32 colour, const std::string& text, bool disabled = false) {
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float mid = at.y + ImGui::GetTextLineHeight() * 0.5f;
    ImGui::GetWindowDrawList()->AddLine(ImVec2(at.x, mid), ImVec2(at.x + 14.0f, mid), colour, 2.0f);
    ImGui::Dummy(ImVec2(18.0f, 0.0f));
    ImGui::SameLine(0.0f, 0.0f);
    ImGui::PushTextWrapPos(0.0f);
    if (disabled) ImGui::TextDisabled("%s", text.c_str());
    else ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
}

}  // namespace

void spectra_section(Explorer& explorer) {
    const auto& lights = explorer.doc.scene.lights;
    const Light* light = nullptr;
    if (!lights.empty()) {
        explorer.view.selected_light = std::clamp(explorer.view.selected_light, 0, static_cast<int>(lights.size()) - 1);
        if (ImGui::BeginCombo(field("light").c_str(), light_entry(lights, explorer.view.selected_light).c_str(), combo_flags())) {
            for (int i = 0; i < static_cast<int>(lights.size()); ++i)
                if (ImGui::Selectable(light_entry(lights, i).c_str(), i == explorer.view.selected_light)) explorer.view.selected_light = i;
            ImGui::EndCombo();
        }
        tooltip("The light whose spectrum is plotted (also: the light last edited in Lights).");
        light = &lights[std::size_t(explorer.view.selected_light)];
    }
    const Material* material = selected_material(explorer);
    SpectrumView view;
    try {
        view = spectrum_view(light, material);
    } catch (const spectral::SpectralError& error) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(ImVec4(1.0f, 0.5f, 0.4f, 1.0f), "%s", error.what());
        ImGui::PopTextWrapPos();
        return;
    }
    spectra_plot(view, ImGui::GetContentRegionAvail().x, 110.0f);
    legend(kLightColour, "light " + std::string(light ? std::to_string(explorer.view.selected_light) + ": " : "") +
                             view.light_label + " (luminance 1; E = 1)");
    const std::string object = "object " + std::to_string(explorer.view.selected_object) + ": ";
    if (view.curves.reflectance.empty()) legend(IM_COL32(120, 120, 120, 255), object + view.no_reflectance, true);
    else legend(kReflectanceColour, object + view.reflectance_label);
}

}  // namespace m3055::explore
