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

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace m3055::explore {

namespace {

std::string light_entry(const std::vector<Light>& lights, int i) {
    const Light& light = lights[std::size_t(i)];
    return "light " + std::to_string(i) + (light.name.empty() ? "" : " \"" + light.name + "\"");
}

// A spectrum's own colour to draw it in: its RGB scaled so the largest
// channel is 1, lifted towards grey when it is too dark to see on the panel.
ImU32 curve_colour(const dvec3& rgb) {
    const double top = std::max({rgb.r, rgb.g, rgb.b});
    dvec3 c = top > 0.0 ? rgb / top : dvec3(0.5);
    c = glm::clamp(c, 0.0, 1.0);
    const double luminance = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    if (luminance < 0.35) c = glm::mix(c, dvec3(1.0), (0.35 - luminance) / (1.0 - luminance));
    return IM_COL32(int(255 * c.r), int(255 * c.g), int(255 * c.b), 255);
}

// A tick's value as the axis shows it.
std::string tick_text(double v) {
    char text[16];
    std::snprintf(text, sizeof text, v >= 10.0 ? "%.0f" : "%.2g", v);
    return text;
}

// The curves in `width` x `height`: the light's on the left axis (its top its
// largest value, at least 1), R on the right axis ([0, 1]), each in its
// spectrum's colour; grid lines every 100 nm and at the axes' ticks; the
// values under the mouse in a tooltip.
void spectra_plot(const SpectrumView& view, float width, float height) {
    const auto& c = view.curves;
    const double top = std::max(1.0, *std::max_element(c.light.begin(), c.light.end()));
    const bool with_r = !c.reflectance.empty();
    const float axis_w = ImGui::CalcTextSize("0.00").x + 6.0f;
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##spectra", ImVec2(width, height));
    const bool hovered = ImGui::IsItemHovered();
    const float label_h = ImGui::GetTextLineHeight();
    const ImVec2 lo(at.x + axis_w, at.y + label_h * 0.5f);
    const ImVec2 hi(at.x + width - (with_r ? axis_w : 4.0f), at.y + height - label_h);  // the wavelengths under it
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImU32 light_colour = curve_colour(view.light_colour), r_colour = curve_colour(view.reflectance_colour);
    const ImU32 grid = IM_COL32(255, 255, 255, 28), label = IM_COL32(255, 255, 255, 150);
    draw->AddRect(lo, hi, IM_COL32(255, 255, 255, 40));
    const auto x_of = [&](double nm) {
        return lo.x + float((nm - c.nm.front()) / (c.nm.back() - c.nm.front())) * (hi.x - lo.x);
    };
    for (int nm = 400; nm <= 700; nm += 100) {
        const float x = x_of(nm);
        draw->AddLine(ImVec2(x, lo.y), ImVec2(x, hi.y), grid);
        const std::string text = std::to_string(nm);
        draw->AddText(ImVec2(std::max(lo.x, x - ImGui::CalcTextSize(text.c_str()).x * 0.5f), hi.y), label, text.c_str());
    }
    // Ticks at 0, half and the top: S on the left in the light's colour, R on the right in R's.
    for (int k = 0; k <= 2; ++k) {
        const float y = hi.y - (hi.y - lo.y) * float(k) / 2.0f;
        if (k > 0) draw->AddLine(ImVec2(lo.x, y), ImVec2(hi.x, y), grid);
        const std::string s = tick_text(top * k / 2.0);
        draw->AddText(ImVec2(lo.x - 4.0f - ImGui::CalcTextSize(s.c_str()).x, y - label_h * 0.5f), light_colour, s.c_str());
        if (with_r) draw->AddText(ImVec2(hi.x + 4.0f, y - label_h * 0.5f), r_colour, tick_text(k / 2.0).c_str());
    }
    // R dashed, as B in the polar plot: the two colours can be alike (gold under a warm light).
    const auto polyline = [&](const std::vector<double>& values, double scale, ImU32 colour, bool dashed) {
        std::vector<ImVec2> points;
        for (std::size_t i = 0; i < values.size(); ++i)
            points.emplace_back(x_of(c.nm[i]), hi.y - float(std::clamp(values[i] / scale, 0.0, 1.0)) * (hi.y - lo.y));
        if (!dashed) return draw->AddPolyline(points.data(), static_cast<int>(points.size()), colour, 0, 2.0f);
        for (std::size_t i = 0; i + 1 < points.size(); ++i)
            if ((i / 3) % 2 == 0) draw->AddLine(points[i], points[i + 1], colour, 2.0f);
    };
    polyline(c.light, top, light_colour, false);
    if (with_r) polyline(c.reflectance, 1.0, r_colour, true);
    if (!hovered) return;
    const float mouse = ImGui::GetIO().MousePos.x;
    const std::size_t i = std::size_t(std::lround(std::clamp((mouse - lo.x) / (hi.x - lo.x), 0.0f, 1.0f) *
                                                  float(c.nm.size() - 1)));
    draw->AddLine(ImVec2(x_of(c.nm[i]), lo.y), ImVec2(x_of(c.nm[i]), hi.y), IM_COL32(255, 255, 255, 90));
    if (!with_r) ImGui::SetTooltip("%.0f nm: S %.3f", c.nm[i], c.light[i]);
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

// The light picker, the plot `plot_h` high (the room's height less the
// legend's lines when 0) and its legend: the section's and the window's.
void spectra_view(Explorer& explorer, float plot_h) {
    const auto& lights = explorer.doc.scene.lights;
    const Light* light = nullptr;
    int& chosen = explorer.view.selected_light;
    if (!lights.empty()) {
        chosen = std::clamp(chosen, 0, static_cast<int>(lights.size()) - 1);
        if (ImGui::BeginCombo(field("light").c_str(), light_entry(lights, chosen).c_str(), combo_flags())) {
            for (int i = 0; i < static_cast<int>(lights.size()); ++i)
                if (ImGui::Selectable(light_entry(lights, i).c_str(), i == chosen)) chosen = i;
            ImGui::EndCombo();
        }
        tooltip("The light whose spectrum is plotted (also: the light last edited in Lights).");
        light = &lights[std::size_t(chosen)];
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
    const float legend_h = 2.5f * ImGui::GetTextLineHeightWithSpacing();
    if (plot_h <= 0.0f) plot_h = std::max(80.0f, ImGui::GetContentRegionAvail().y - legend_h);
    spectra_plot(view, ImGui::GetContentRegionAvail().x, plot_h);
    legend(curve_colour(view.light_colour), "S, left: light " +
                                                 std::string(light ? std::to_string(chosen) + ": " : "") +
                                                 view.light_label + " (luminance 1; E = 1)");
    const std::string object = "object " + std::to_string(explorer.view.selected_object) + ": ";
    if (view.curves.reflectance.empty()) legend(IM_COL32(120, 120, 120, 255), object + view.no_reflectance, true);
    else legend(curve_colour(view.reflectance_colour), "R (dashed), right: " + object + view.reflectance_label);
}

}  // namespace

void spectra_section(Explorer& explorer) {
    spectra_view(explorer, 110.0f);
    if (ImGui::SmallButton("larger: View > Spectra")) {
        explorer.view.show_spectra = true;
        explorer.view.show_brdf_views = false;
    }
    tooltip("The same plot in a window of its own, docked beside the plots.");
}

void draw_spectra(Explorer& explorer, float x, float y, float width, float height) {
    if (!explorer.view.show_spectra) return;
    // Docked beside the plots, as the BRDF views: opaque, fixed, never over the display.
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    ImGui::SetNextWindowBgAlpha(1.0f);
    constexpr ImGuiWindowFlags kDocked = ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove |
                                         ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse;
    if (ImGui::Begin("Spectra", &explorer.view.show_spectra, kDocked)) spectra_view(explorer, 0.0f);
    ImGui::End();
}

}  // namespace m3055::explore
