#include "explore/polar_plot.h"

#include "reference/reference.h"

#include <glm/geometric.hpp>
#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace m3055::explore {

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
}

double incidence_towards_camera(const Light& light, const Camera& camera) {
    const dvec3 N = glm::normalize(camera.position - camera.target);
    // A point or spot light: its direction as seen from the target.
    const dvec3 L = light.type == LightType::directional
                        ? glm::normalize(light.direction)
                        : glm::normalize(light.position - camera.target);
    return std::acos(std::clamp(glm::dot(N, L), -1.0, 1.0)) / kDeg;
}

void polar_plot(const Material& material, const Light& light, double incidence_deg, float size) {
    // The plane of incidence is the x-y plane, N = +y; L on the left (-x).
    const dvec3 N(0.0, 1.0, 0.0);
    Light plotted = light;  // keep intensity, colour and own lobes
    plotted.type = LightType::directional;
    plotted.enabled = true;
    plotted.direction = {-std::sin(incidence_deg * kDeg), std::cos(incidence_deg * kDeg), 0.0};
    const std::vector<Light> lights = {plotted};

    constexpr int kSteps = 180;  // one sample a degree
    dvec3 values[kSteps + 1];
    double top = 1.0;  // the radius of the outer circle: at least display white
    for (int i = 0; i <= kSteps; ++i) {
        const double view = (-90.0 + i) * kDeg;
        const ref::SurfacePoint point{dvec3(0.0), N, dvec3(std::sin(view), std::cos(view), 0.0)};
        values[i] = ref::shade_opaque(material, lights, point);
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(values[i][c])) values[i][c] = 0.0;
            top = std::max(top, values[i][c]);
        }
    }

    const float radius = size * 0.5f - 6.0f;
    const ImVec2 corner = ImGui::GetCursorScreenPos();
    ImGui::Dummy(ImVec2(size, radius + 8.0f + ImGui::GetTextLineHeightWithSpacing()));
    const ImVec2 origin(corner.x + size * 0.5f, corner.y + radius + 4.0f);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    auto at = [&](double angle_deg, double r) {  // angle from N, positive to the right
        return ImVec2(origin.x + static_cast<float>(std::sin(angle_deg * kDeg) * r),
                      origin.y - static_cast<float>(std::cos(angle_deg * kDeg) * r));
    };

    // Grid: half circles at quarter steps of `top`; 1.0 (display white) is bold.
    for (int k = 1; k <= 4; ++k) {
        const double r = radius * k / 4.0;
        for (int a = -90; a < 90; a += 3) draw->AddLine(at(a, r), at(a + 3, r), IM_COL32(255, 255, 255, 35));
    }
    const double white = radius / top;
    for (int a = -90; a < 90; a += 2) draw->AddLine(at(a, white), at(a + 2, white), IM_COL32(255, 255, 255, 110), 1.5f);
    draw->AddLine(at(-90, radius), at(90, radius), IM_COL32(255, 255, 255, 80));  // the surface
    draw->AddLine(origin, at(0, radius), IM_COL32(255, 255, 255, 80));            // N
    // L (yellow) and the mirror direction R (grey, dashed by short segments).
    draw->AddLine(origin, at(-incidence_deg, radius), IM_COL32(255, 220, 60, 255), 2.0f);
    for (int s = 0; s < 10; s += 2) {
        draw->AddLine(at(incidence_deg, radius * s / 10.0), at(incidence_deg, radius * (s + 1) / 10.0),
                      IM_COL32(200, 200, 200, 200), 1.5f);
    }
    // One curve per channel, radius = value / top.
    const ImU32 colours[3] = {IM_COL32(255, 80, 80, 255), IM_COL32(80, 230, 80, 255),
                              IM_COL32(90, 140, 255, 255)};
    for (int c = 0; c < 3; ++c) {
        ImVec2 points[kSteps + 1];
        for (int i = 0; i <= kSteps; ++i) points[i] = at(-90.0 + i, values[i][c] * radius / top);
        draw->AddPolyline(points, kSteps + 1, colours[c], 0, 1.8f);
    }
    draw->AddText(ImVec2(origin.x + 4, corner.y), IM_COL32(255, 255, 255, 140), "N");
    const ImVec2 l_tip = at(-incidence_deg, radius * 0.75);
    draw->AddText(ImVec2(l_tip.x - 14, l_tip.y - 16), IM_COL32(255, 220, 60, 255), "L");
    const ImVec2 r_tip = at(incidence_deg, radius * 0.75);
    draw->AddText(ImVec2(r_tip.x + 4, r_tip.y - 16), IM_COL32(200, 200, 200, 255), "R");
    char scale[64];
    std::snprintf(scale, sizeof scale, "outer circle %.2f, bold = 1 (display white)", top);
    draw->AddText(ImVec2(corner.x, origin.y + 4), IM_COL32(255, 255, 255, 140), scale);
}

}  // namespace m3055::explore
