#include "explore_ui/light_widgets.h"

#include "explore_ui/widgets.h"
#include "scene/light_direction.h"

#include <imgui.h>

#include <cmath>

namespace m3055::explore {

bool light_sphere_widget(const char* id, dvec3* direction, float radius) {
    const float outer = radius * static_cast<float>(1.0 + kBackRing);
    const ImVec2 corner = ImGui::GetCursorScreenPos();
    const ImVec2 centre(corner.x + outer, corner.y + outer);
    ImGui::InvisibleButton(id, ImVec2(2 * outer, 2 * outer));

    bool changed = false;
    if (ImGui::IsItemActive()) {
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        // Screen y grows downwards; the disc's y is up.
        const DiscPoint p{(mouse.x - centre.x) / radius, -(mouse.y - centre.y) / radius};
        const dvec3 d = direction_from_disc(p);
        if (d != *direction) {
            *direction = d;
            changed = true;
        }
    }

    ImDrawList* draw = ImGui::GetWindowDrawList();
    // Back ring: dark, with the word "back" so its meaning is discoverable.
    draw->AddCircleFilled(centre, outer, IM_COL32(38, 40, 48, 255), 48);
    draw->AddText(ImVec2(centre.x - 14, corner.y + 1), IM_COL32(120, 120, 130, 255), "back");
    // Front hemisphere: concentric discs lit from the upper left, to read as a ball.
    for (int i = 10; i >= 1; --i) {
        const float t = i / 10.0f;
        const int v = static_cast<int>(70 + 110 * (1.0f - t * t));
        draw->AddCircleFilled(ImVec2(centre.x - radius * 0.25f * (1 - t), centre.y - radius * 0.25f * (1 - t)),
                              radius * t, IM_COL32(v, v, v + 10, 255), 40);
    }
    draw->AddCircle(centre, radius, IM_COL32(200, 200, 210, 255), 48);
    // Cross-hair through the centre (the direction towards the viewer).
    draw->AddLine(ImVec2(centre.x - outer, centre.y), ImVec2(centre.x + outer, centre.y),
                  IM_COL32(255, 255, 255, 40));
    draw->AddLine(ImVec2(centre.x, centre.y - outer), ImVec2(centre.x, centre.y + outer),
                  IM_COL32(255, 255, 255, 40));
    // The light: yellow in front, orange behind.
    const DiscPoint p = disc_from_direction(*direction);
    const ImVec2 dot(centre.x + static_cast<float>(p.x) * radius,
                     centre.y - static_cast<float>(p.y) * radius);
    const bool front = direction->z >= 0.0;
    draw->AddCircleFilled(dot, 5.0f, front ? IM_COL32(255, 230, 80, 255) : IM_COL32(255, 140, 40, 255));
    draw->AddCircle(dot, 5.0f, IM_COL32(0, 0, 0, 255));
    if (tooltip_due()) {
        ImGui::SetTooltip("Drag: the light's direction as seen from the camera.\n"
                          "Inner disc = in front of the object, outer ring = behind it.");
    }
    return changed;
}

bool light_angle_sliders(dvec3* direction, double* azimuth_memory) {
    Angles angles = angles_from_direction(*direction, *azimuth_memory);
    bool changed = slider_double("azimuth", &angles.azimuth_deg, -180.0, 180.0, "%.1f deg");
    tooltip("direction towards the light, turned about the scene's up axis, in [-180, 180] deg "
            "(scene/light_direction.h)");
    changed |= slider_double("elevation", &angles.elevation_deg, -90.0, 90.0, "%.1f deg");
    tooltip("direction towards the light, above (+) or below (-) the horizon, in [-90, 90] deg");
    *azimuth_memory = angles.azimuth_deg;
    if (changed) *direction = direction_from_angles(angles);
    return changed;
}

}  // namespace m3055::explore
