// The "BRDF views" window (View > BRDF views): BRDF Explorer's θh/θd slice,
// directional albedo and 3D lobe of the selected material, drawn with ImGui's
// draw list from renderer/analysis/brdf_views.h (the numbers `m3055 plot`
// writes). Only the open tab is computed, and only when the material (or, for
// the lobe, the plotted light's incidence) changed: BrdfViews keeps the rest.
#include "explore_ui/panels.h"

#include "analysis/brdf_views.h"
#include "explore_ui/widgets.h"
#include "numeric/angles.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <string>

namespace m3055::explore {

namespace {

using numeric::kDegree;
const ImU32 kAxis = IM_COL32(255, 255, 255, 90), kLabel = IM_COL32(220, 220, 220, 255);

// Black, red, yellow, white over [0, 1] (gnuplot's "hot", as `m3055 plot`).
ImU32 heat(double t) {
    t = std::clamp(t, 0.0, 1.0);
    const auto c = [](double x) { return int(255.0 * std::clamp(x, 0.0, 1.0)); };
    return IM_COL32(c(3.0 * t), c(3.0 * t - 1.0), c(3.0 * t - 2.0), 255);
}

// The colour of value v: linear from 0 to top, or log over 4 decades below top.
double shade(double v, double top, bool log) {
    if (!(v > 0.0) || !(top > 0.0)) return 0.0;
    return log ? (std::log10(v / top) + 4.0) / 4.0 : v / top;
}

// The slice's and plots' side: the room less the axis labels and the colour
// bar, and no taller than the room less `below` (what goes under and above
// it), so the whole view shows in the docked window (1280 x 720 included).
float side_of_square(float below, float aspect = 1.0f) {
    const ImVec2 room = ImGui::GetContentRegionAvail();
    return std::clamp(std::min(room.x - 135.0f, (room.y - below) / aspect), 60.0f, 360.0f);
}

// The colour bar right of the slice: the heat map from 0 (bottom) to the
// largest value (top), labelled with the values at its ends.
void colour_bar(ImDrawList* draw, const ImVec2& bottom_left, float height, double top, bool log) {
    constexpr float kWidth = 12.0f;
    constexpr int kSteps = 64;
    for (int k = 0; k < kSteps; ++k) {
        const float y0 = bottom_left.y - height * float(k + 1) / kSteps, y1 = bottom_left.y - height * float(k) / kSteps;
        draw->AddRectFilled(ImVec2(bottom_left.x, y0), ImVec2(bottom_left.x + kWidth, y1 + 0.5f),
                            heat((double(k) + 0.5) / kSteps));
    }
    draw->AddRect(ImVec2(bottom_left.x, bottom_left.y - height), ImVec2(bottom_left.x + kWidth, bottom_left.y), kAxis);
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", top);
    draw->AddText(ImVec2(bottom_left.x + kWidth + 3, bottom_left.y - height - 6), kLabel, text);
    std::snprintf(text, sizeof text, "%.3g", log ? top * 1e-4 : 0.0);
    draw->AddText(ImVec2(bottom_left.x + kWidth + 3, bottom_left.y - 8), kLabel, text);
}

void slice_view(const ThetaSlice& slice, bool log) {
    const float line = ImGui::GetTextLineHeightWithSpacing();
    const float size = side_of_square(18.0f + 40.0f + 2.0f * line), left = 44.0f, top_margin = 18.0f;
    const float cell = size / float(slice.n);
    const ImVec2 corner = ImGui::GetCursorScreenPos();
    ImGui::Dummy(ImVec2(left + size, top_margin + size + 40.0f));
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 origin(corner.x + left, corner.y + top_margin + size);  // theta_h = theta_d = 0: bottom left
    const double top = slice.max_value();
    for (int j = 0; j < slice.n; ++j)
        for (int i = 0; i < slice.n; ++i) {
            const bool below = slice.below[std::size_t(j * slice.n + i)];
            const ImVec2 a(origin.x + i * cell, origin.y - (j + 1) * cell);
            draw->AddRectFilled(a, ImVec2(a.x + cell + 0.5f, a.y + cell + 0.5f),
                                heat(below ? 0.0 : shade(slice.at(i, j), top, log)));
        }
    for (int deg = 0; deg <= 90; deg += 30) {  // the angles on both axes
        const float t = size * float(deg) / 90.0f;
        const std::string text = std::to_string(deg);
        draw->AddLine(ImVec2(origin.x + t, origin.y), ImVec2(origin.x + t, origin.y + 4), kAxis);
        draw->AddText(ImVec2(origin.x + t - 6, origin.y + 5), kLabel, text.c_str());
        draw->AddLine(ImVec2(origin.x - 4, origin.y - t), ImVec2(origin.x, origin.y - t), kAxis);
        draw->AddText(ImVec2(origin.x - 24, origin.y - t - 7), kLabel, text.c_str());
    }
    draw->AddText(ImVec2(origin.x + size * 0.5f - 50, origin.y + 20), kLabel, "theta_h (deg)");
    draw->AddText(ImVec2(corner.x, corner.y - 2), kLabel, "theta_d");
    colour_bar(draw, ImVec2(origin.x + size + 8.0f, origin.y), size, top, log);
    ImGui::TextWrapped("phi_d = 90 deg; %s colour, max f = %.4g (white)", log ? "log10 (4 decades)" : "linear", top);
}

void albedo_view(const AlbedoCurve& curve) {
    double top = 1.2, peak = 0.0, at = 0.0;
    for (std::size_t k = 0; k < curve.albedo.size(); ++k)
        if (std::isfinite(curve.albedo[k]) && curve.albedo[k] > peak) peak = curve.albedo[k], at = curve.view_deg[k];
    top = std::max(top, peak * 1.1);
    const float width = side_of_square(26.0f + 3.0f * ImGui::GetTextLineHeightWithSpacing(), 0.6f);
    const float height = width * 0.6f, left = 44.0f;
    const ImVec2 corner = ImGui::GetCursorScreenPos();
    ImGui::Dummy(ImVec2(left + width, height + 26.0f));
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 origin(corner.x + left, corner.y + height);
    const auto point = [&](double deg, double a) {
        return ImVec2(origin.x + float(deg / 90.0) * width, origin.y - float(a / top) * height);
    };
    draw->AddRect(ImVec2(origin.x, corner.y), ImVec2(origin.x + width, origin.y), kAxis);
    for (int deg = 0; deg <= 90; deg += 30)
        draw->AddText(ImVec2(point(deg, 0).x - 6, origin.y + 4), kLabel, std::to_string(deg).c_str());
    for (double a = 0.0; a <= top; a += top > 3 ? 1.0 : 0.5) {
        char text[16];
        std::snprintf(text, sizeof text, "%.1f", a);
        draw->AddText(ImVec2(corner.x + 8, point(0, a).y - 7), kLabel, text);
    }
    for (int deg = 0; deg < 90; deg += 4)  // the white furnace's limit, dashed
        draw->AddLine(point(deg, 1.0), point(deg + 2, 1.0), IM_COL32(255, 255, 255, 140));
    for (std::size_t k = 1; k < curve.albedo.size(); ++k) {
        const double a0 = curve.albedo[k - 1], a1 = curve.albedo[k];
        if (std::isfinite(a0) && std::isfinite(a1))
            draw->AddLine(point(curve.view_deg[k - 1], a0), point(curve.view_deg[k], a1), IM_COL32(255, 200, 80, 255),
                          2.0f);
    }
    ImGui::TextWrapped("view angle theta_v (deg); %zu incident samples per view (cosine midpoint rule, on the GPU)",
                       curve.samples);
    ImGui::TextColored(peak > 1.01 ? ImVec4(1, 0.8f, 0.3f, 1) : ImVec4(0.6f, 1, 0.6f, 1),
                       "max albedo %.4f at %.0f deg%s", peak, at, peak > 1.01 ? ": energy gain (> 1)" : " (<= 1)");
}

// Orthographic view of the lobe turned by yaw (about N) and pitch (elevation).
void lobe_view(Explorer& explorer, const Lobe3d& lobe) {
    const float size = side_of_square(ImGui::GetTextLineHeightWithSpacing() + 32.0f, 0.8f) + 40.0f;
    const ImVec2 corner = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("lobe", ImVec2(size, size * 0.8f));
    if (ImGui::IsItemActive()) {  // a drag turns it
        explorer.view.lobe_yaw += ImGui::GetIO().MouseDelta.x * 0.01f;
        explorer.view.lobe_pitch = std::clamp(explorer.view.lobe_pitch + ImGui::GetIO().MouseDelta.y * 0.01f, -1.5f, 1.5f);
    }
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 centre(corner.x + size * 0.5f, corner.y + size * 0.6f);
    const double cy = std::cos(explorer.view.lobe_yaw), sy = std::sin(explorer.view.lobe_yaw);
    const double cp = std::cos(explorer.view.lobe_pitch), sp = std::sin(explorer.view.lobe_pitch);
    const float scale = size * 0.42f;
    const auto project = [&](const dvec3& p) {
        const double x = p.x * cy - p.y * sy, y = p.x * sy + p.y * cy;
        return ImVec2(centre.x + float(x) * scale, centre.y - float(p.z * cp + y * sp) * scale);
    };
    for (int a = 0; a < 72; ++a)  // the horizon and N
        draw->AddLine(project({std::cos(a * 5 * kDegree), std::sin(a * 5 * kDegree), 0}),
                      project({std::cos((a + 1) * 5 * kDegree), std::sin((a + 1) * 5 * kDegree), 0}), kAxis);
    draw->AddLine(project(dvec3(0.0)), project({0, 0, 1}), kAxis);
    const auto tip = [&](int t, int p) {
        const std::size_t k = std::size_t(t * lobe.np + p);
        return std::make_pair(project(lobe.V[k] * (lobe.value[k] / lobe.top)), heat(0.25 + 0.75 * lobe.value[k] / lobe.top));
    };
    for (int t = 0; t < lobe.nt; ++t)
        for (int p = 0; p < lobe.np; ++p) {
            const auto [here, colour] = tip(t, p);
            if (p + 1 < lobe.np && t % 3 == 0) draw->AddLine(here, tip(t, p + 1).first, colour);
            if (t + 1 < lobe.nt && p % 3 == 0) draw->AddLine(here, tip(t + 1, p).first, colour);
        }
    draw->AddLine(project(lobe.L), project(dvec3(0.0)), IM_COL32(255, 220, 60, 255), 2.0f);
    draw->AddText(project(lobe.L), IM_COL32(255, 220, 60, 255), "L");
    ImGui::Text("f (N.L), max %.4g scaled to 1; drag to turn", lobe.top);
}

}  // namespace

void draw_brdf_views(Explorer& explorer, BrdfViews* views_cache, float x, float y, float width, float height) {
    if (!explorer.view.show_brdf_views || !views_cache) return;
    const Material* material = selected_material(explorer);
    // Docked beside the plots (the strip's room: explore.cpp), opaque, fixed:
    // never over the display.
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    ImGui::SetNextWindowBgAlpha(1.0f);
    constexpr ImGuiWindowFlags kDocked = ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove |
                                         ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse;
    if (!ImGui::Begin("BRDF views", &explorer.view.show_brdf_views, kDocked) || !material) {
        ImGui::End();
        return;
    }
    ImGui::Text("object %d (%s)", explorer.view.selected_object, material->model().label.c_str());
    try {
        BrdfViews& views = *views_cache;
        if (ImGui::BeginTabBar("views")) {
            if (ImGui::BeginTabItem("theta_h / theta_d")) {
                ImGui::Checkbox("log colour", &explorer.view.views_log);
                slice_view(views.slice(*material), explorer.view.views_log);
                ImGui::EndTabItem();
            }
            if (ImGui::BeginTabItem("albedo")) {
                albedo_view(views.albedo(*material));
                ImGui::EndTabItem();
            }
            if (ImGui::BeginTabItem("3D lobe")) {
                const double incidence = explorer.doc.scene.lights.empty() ? 45.0 : std::min(89.0,
                    incidence_at_target(explorer.doc.scene.lights[std::size_t(std::clamp(explorer.view.plotted_light, 0,
                        int(explorer.doc.scene.lights.size()) - 1))], explorer.doc.scene.camera));
                ImGui::Text("incidence %.1f deg (the polar plot's light)", incidence);
                lobe_view(explorer, views.lobe(*material, incidence));
                ImGui::EndTabItem();
            }
            ImGui::EndTabBar();
        }
    } catch (const std::exception& e) {  // a model the grid cannot evaluate (translucent)
        ImGui::TextColored(ImVec4(1, 0.43f, 0.43f, 1), "%s", e.what());
    }
    ImGui::End();
}

}  // namespace m3055::explore
