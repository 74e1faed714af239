// The Lights panel's top-down light plot (three-point lighting): the subject
// in the middle, each light an arrow pointing at it from its azimuth, named
// (key / fill / back when a three-point preset made them), a rect's or disk's
// outline at the arrow's tail (to the scale of the light's distance), the sky
// a ring around it all; dragging an arrow turns that light in azimuth (its
// elevation and distance are kept, a rect or disk turns its facing with it:
// explore/light_plan.h). Under it
// the key-to-fill ratio at the subject's centre, from renderer/analysis/
// lighting_ratio.h (the function grading uses), updated live.
#include "explore_ui/panels.h"

#include "explore/light_plan.h"
#include "explore_ui/widgets.h"
#include "numeric/angles.h"

#include <imgui.h>

#include <cmath>
#include <string>
#include <vector>

namespace m3055::explore {

namespace {

using numeric::kDegree;

// Seen from above (+y): +x right, +z (towards the default camera) down.
ImVec2 plan_direction(const Light& light, const dvec3& subject) {
    const dvec3 d = light.type == LightType::directional ? light.direction : light.position - subject;
    const double length = std::hypot(d.x, d.z);
    if (length < 1e-9) return ImVec2(0.0f, 0.0f);  // straight above or below
    return ImVec2(static_cast<float>(d.x / length), static_cast<float>(d.z / length));
}

// Seen from above at the light's own distance: the plot's pixels per scene
// unit that put the light's tail `reach` pixels from the subject.
float plan_scale(const Light& light, const dvec3& subject, float reach) {
    const double distance = std::hypot(light.position.x - subject.x, light.position.z - subject.z);
    return distance > 1e-9 ? static_cast<float>(reach / distance) : 0.0f;
}

}  // namespace

void light_plot(Explorer& explorer) {
    int& dragged = explorer.view.dragged_light;
    const auto& lights = explorer.doc.scene.lights;
    const LightPlanReadouts& plan =
        update_light_plan(explorer.session.light_plan, explorer.doc.scene, explorer.doc.revision);
    const dvec3& subject = plan.subject;
    const float size = 150.0f, reach = size * 0.5f - 14.0f;
    const ImVec2 corner = ImGui::GetCursorScreenPos();
    const ImVec2 centre(corner.x + size * 0.5f, corner.y + size * 0.5f);
    ImGui::InvisibleButton("##light plot", ImVec2(size, size));
    tooltip("Seen from above, the camera at the bottom. Drag an arrow to turn its light about the subject (a rect "
            "or disk turns to keep facing it). Rects and disks are outlined to scale at their distance; a ring is "
            "the sky.");
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(corner, ImVec2(corner.x + size, corner.y + size), true);  // a large emitter stays inside
    draw->AddRect(corner, ImVec2(corner.x + size, corner.y + size), IM_COL32(255, 255, 255, 40));
    draw->AddCircleFilled(centre, 9.0f, IM_COL32(170, 170, 170, 255));
    draw->AddText(ImVec2(centre.x - 18, corner.y + size - 16), IM_COL32(255, 255, 255, 110), "camera");
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    if (ImGui::IsItemActivated()) {  // the arrow nearest the press
        float best = 1e9f;
        for (int i = 0; i < static_cast<int>(lights.size()); ++i) {
            if (lights[std::size_t(i)].type == LightType::sky) continue;  // everywhere: no arrow to turn
            const ImVec2 d = plan_direction(lights[std::size_t(i)], subject);
            const float dx = centre.x + d.x * reach - mouse.x, dy = centre.y + d.y * reach - mouse.y;
            if (dx * dx + dy * dy < best) best = dx * dx + dy * dy, dragged = i;
        }
    }
    if (ImGui::IsItemActive() && dragged >= 0 && dragged < static_cast<int>(lights.size()) &&
        (mouse.x != centre.x || mouse.y != centre.y)) {
        Light turned = lights[std::size_t(dragged)];
        turn_to_azimuth(turned, subject, std::atan2(mouse.x - centre.x, mouse.y - centre.y) / kDegree);
        if (ImGui::GetIO().MouseDelta.x != 0.0f || ImGui::GetIO().MouseDelta.y != 0.0f)
            explorer.commands.push(command::SetLight{dragged, turned});
    }
    if (!ImGui::IsItemActive()) dragged = -1;
    for (int i = 0; i < static_cast<int>(lights.size()); ++i) {
        const Light& light = lights[std::size_t(i)];
        const std::string label = light.name.empty() ? std::to_string(i) : light.name;
        if (light.type == LightType::sky) {
            const ImU32 sky = light.enabled ? IM_COL32(110, 170, 255, 200) : IM_COL32(120, 120, 120, 200);
            draw->AddCircle(centre, size * 0.5f - 4.0f, sky, 48, 2.0f);
            draw->AddText(ImVec2(corner.x + 4, corner.y + 2), sky, ("sky: " + label).c_str());
            continue;
        }
        const ImVec2 d = plan_direction(light, subject);
        const ImVec2 tail(centre.x + d.x * reach, centre.y + d.y * reach), head(centre.x + d.x * 14.0f, centre.y + d.y * 14.0f);
        const ImU32 colour = !light.enabled ? IM_COL32(120, 120, 120, 255)
                             : i == dragged ? IM_COL32(255, 255, 255, 255)
                                            : IM_COL32(255, 220, 60, 255);
        const std::vector<PlanPoint> outline = emitter_outline(light);
        if (!outline.empty()) {
            const float scale = plan_scale(light, subject, reach);
            std::vector<ImVec2> points;
            for (const PlanPoint& p : outline)
                points.push_back(ImVec2(tail.x + float(p.x) * scale, tail.y + float(p.z) * scale));
            draw->AddPolyline(points.data(), static_cast<int>(points.size()), colour, ImDrawFlags_Closed, 2.0f);
        }
        draw->AddLine(tail, head, colour, 2.0f);
        draw->AddTriangleFilled(head, ImVec2(head.x + d.x * 7 - d.y * 4, head.y + d.y * 7 + d.x * 4),
                                ImVec2(head.x + d.x * 7 + d.y * 4, head.y + d.y * 7 - d.x * 4), colour);
        draw->AddText(ImVec2(tail.x - 8, tail.y - 7), colour, label.c_str());
    }
    draw->PopClipRect();
    ImGui::TextWrapped("key-to-fill at the subject: %s", plan.ratio.text().c_str());
    tooltip("The irradiance of the light named \"key\" against the one named \"fill\" at the subject's centre, "
            "on a surface facing the camera (renderer/analysis/lighting_ratio.h), as n:1 and in stops (log2).");
}

}  // namespace m3055::explore
