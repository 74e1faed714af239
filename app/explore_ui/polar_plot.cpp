#include "explore_ui/polar_plot.h"

#include "numeric/angles.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <vector>

namespace m3055::explore {

namespace {
using numeric::kDegree;

// The grid: half circles at quarter steps (linear) or at each decade (log),
// and display white (1.0) bold.
void draw_grid(ImDrawList* draw, const ImVec2& origin, float radius, RadialScale scale, double top,
               const std::function<ImVec2(double, double)>& at) {
    auto half_circle = [&](double r, ImU32 colour, float thickness) {
        for (int a = -90; a < 90; a += 3) draw->AddLine(at(a, r), at(a + 3, r), colour, thickness);
    };
    if (scale == RadialScale::log) {
        for (double v = 1e-2; v < top * 1.001; v *= 10.0)
            half_circle(radius * radial_fraction(v, scale, top), IM_COL32(255, 255, 255, 35), 1.0f);
    } else {
        for (int k = 1; k <= 4; ++k) half_circle(radius * k / 4.0, IM_COL32(255, 255, 255, 35), 1.0f);
    }
    const double white = radial_fraction(1.0, scale, top);
    if (white <= 1.0) half_circle(radius * white, IM_COL32(255, 255, 255, 110), 1.5f);
    draw->AddLine(at(-90, radius), at(90, radius), IM_COL32(255, 255, 255, 80));  // the surface
    draw->AddLine(origin, at(0, radius), IM_COL32(255, 255, 255, 80));            // N
}
// One line per channel; beyond the outer circle it is drawn on it (returns
// whether any value was). Dashed: every other run of four segments.
bool draw_curve(ImDrawList* draw, const PlaneCurve& curve, RadialScale scale, double top, float radius,
                const std::function<ImVec2(double, double)>& at, bool dashed) {
    const ImU32 colours[3] = {IM_COL32(255, 80, 80, 255), IM_COL32(80, 230, 80, 255), IM_COL32(90, 140, 255, 255)};
    bool clipped = false;
    const int n = static_cast<int>(curve.values.size());
    std::vector<ImVec2> points(static_cast<std::size_t>(n));
    for (int c = 0; c < 3; ++c) {
        for (int i = 0; i < n; ++i) {
            const double f = radial_fraction(curve.values[i][c], scale, top);
            clipped |= f > 1.0;
            points[i] = at(curve.view_deg[i], std::min(f, 1.0) * radius);
        }
        if (!dashed) {
            draw->AddPolyline(points.data(), n, colours[c], 0, 1.8f);
            continue;
        }
        for (int i = 0; i + 1 < n; ++i)
            if ((i / 4) % 2 == 0) draw->AddLine(points[i], points[i + 1], colours[c], 1.8f);
    }
    return clipped;
}

}  // namespace

void polar_plot(const PlaneCurve& curve, RadialScale scale, double top, float size, const PlaneCurve* b) {
    const float radius = size * 0.5f - 6.0f;
    const ImVec2 corner = ImGui::GetCursorScreenPos();
    ImGui::Dummy(ImVec2(size, radius + 8.0f + ImGui::GetTextLineHeightWithSpacing()));
    const ImVec2 origin(corner.x + size * 0.5f, corner.y + radius + 4.0f);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const std::function<ImVec2(double, double)> at = [&](double angle_deg, double r) {  // from N, + to the right
        return ImVec2(origin.x + static_cast<float>(std::sin(angle_deg * kDegree) * r),
                      origin.y - static_cast<float>(std::cos(angle_deg * kDegree) * r));
    };
    draw_grid(draw, origin, radius, scale, top, at);

    const double incidence = curve.incidence_deg;
    if (!curve.light_behind) {
        // L (yellow) and the mirror direction R (grey, dashed by short segments).
        draw->AddLine(origin, at(-incidence, radius), IM_COL32(255, 220, 60, 255), 2.0f);
        for (int s = 0; s < 10; s += 2)
            draw->AddLine(at(incidence, radius * s / 10.0), at(incidence, radius * (s + 1) / 10.0),
                          IM_COL32(200, 200, 200, 200), 1.5f);
        const ImVec2 l_tip = at(-incidence, radius * 0.75), r_tip = at(incidence, radius * 0.75);
        draw->AddText(ImVec2(l_tip.x - 14, l_tip.y - 16), IM_COL32(255, 220, 60, 255), "L");
        draw->AddText(ImVec2(r_tip.x + 4, r_tip.y - 16), IM_COL32(200, 200, 200, 255), "R");
    }
    bool clipped = draw_curve(draw, curve, scale, top, radius, at, false);
    if (b) clipped |= draw_curve(draw, *b, scale, top, radius, at, true);
    draw->AddText(ImVec2(origin.x + 4, corner.y), IM_COL32(255, 255, 255, 140), "N");
    // Legend, top left: the curves are the colour's channels; L the light, R its mirror; B dashed.
    {
        const ImU32 channel[3] = {IM_COL32(255, 80, 80, 255), IM_COL32(80, 230, 80, 255), IM_COL32(90, 140, 255, 255)};
        const char* names[3] = {"red", "green", "blue"};
        const float line = ImGui::GetTextLineHeight();
        float x = corner.x;
        for (int c = 0; c < 3; ++c) {
            draw->AddText(ImVec2(x, corner.y), channel[c], names[c]);
            x += ImGui::CalcTextSize(names[c]).x + 6.0f;
        }
        draw->AddText(ImVec2(corner.x, corner.y + line), IM_COL32(255, 255, 255, 140), b ? "channels; B dashed" : "channels");
    }
    if (curve.light_behind) {
        const char* text = "light behind the surface: no lobe";
        const ImVec2 extent = ImGui::CalcTextSize(text);
        draw->AddText(ImVec2(origin.x - extent.x * 0.5f, origin.y - radius * 0.5f), IM_COL32(255, 200, 80, 255), text);
    }
    char label[128];
    if (scale == RadialScale::log) std::snprintf(label, sizeof label, "log: centre 0.001, outer %.3g", top);
    else if (scale == RadialScale::lobe) std::snprintf(label, sizeof label, "lobe: outer %.3g, bold = 1 (white)", top);
    else std::snprintf(label, sizeof label, "outer %.3g, bold = 1 (white)", top);
    if (clipped) std::strncat(label, "; beyond: on it", sizeof label - std::strlen(label) - 1);
    draw->AddText(ImVec2(corner.x, origin.y + 4), clipped ? IM_COL32(255, 170, 60, 255) : IM_COL32(255, 255, 255, 140),
                  label);
}

}  // namespace m3055::explore
