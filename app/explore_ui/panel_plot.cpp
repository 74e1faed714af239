// The bottom strip's polar plot: its header picks the light plotted and the
// radial scale (both kept until the user changes them), and says what is
// plotted (reflected value, or the displayed blend for translucent objects).
#include "explore_ui/panels.h"

#include "explore/plot_scale.h"

#include "analysis/plane_curve_gpu.h"
#include "explore_ui/polar_plot.h"
#include "explore_ui/widgets.h"

#include <imgui.h>

#include <algorithm>
#include <optional>
#include <string>

namespace m3055::explore {

namespace {

std::string light_label(const Scene& scene, int i) {
    const Light& light = scene.lights[std::size_t(i)];
    return "light " + std::to_string(i) + (light.name.empty() ? "" : " \"" + light.name + "\"");
}

void light_combo(Explorer& explorer) {
    const int count = static_cast<int>(explorer.doc.scene.lights.size());
    explorer.view.plotted_light = std::clamp(explorer.view.plotted_light, 0, count - 1);
    ImGui::SetNextItemWidth(110.0f);
    if (ImGui::BeginCombo("##plotted light", light_label(explorer.doc.scene, explorer.view.plotted_light).c_str())) {
        for (int i = 0; i < count; ++i)
            if (ImGui::Selectable(light_label(explorer.doc.scene, i).c_str(), i == explorer.view.plotted_light)) explorer.view.plotted_light = i;
        ImGui::EndCombo();
    }
    tooltip("The light the plot shows (it stays until you pick another here).");
}

// The scale combo; model_max's top is the model's largest value (plane_curve.h),
// recomputed only when the material or the light changes, not with the angle.
double scale_combo(Explorer& explorer, PlaneCurves* curves, const Material& material, const Light& light) {
    int scale = static_cast<int>(explorer.view.plot_scale);
    ImGui::SetNextItemWidth(100.0f);
    if (ImGui::Combo("##scale", &scale, "fixed\0model max\0log\0lobe\0")) {
        explorer.view.plot_scale = static_cast<RadialScale>(scale);
        explorer.view.plot_top = explorer.view.plot_scale == RadialScale::log ? 1000.0 : 1.0;
    }
    tooltip("Radial scale: fixed (the outer circle's value below), the model's largest value over "
            "incidences 0-85 deg, logarithmic (0.001 at the centre), or lobe (the default: the largest value "
            "plotted now, rounded up to 1, 2 or 5 x 10^k). Kept until changed here.");
    if (explorer.view.plot_scale == RadialScale::lobe) return 0.0;  // plot_section takes it from the curves
    if (explorer.view.plot_scale == RadialScale::model_max) {
        static Material cached_material;
        static Light cached_light;
        static double cached_top = 1.0;
        if (!(cached_material == material) || cached_light.intensity != light.intensity ||
            cached_light.color != light.color || cached_light.lobes.size() != light.lobes.size()) {
            cached_material = material;
            cached_light = light;
            cached_top = std::max(1e-6, curves ? curves->model_max(material, light, dvec3(0.0))
                                                           : model_max(material, light, dvec3(0.0)));
        }
        return cached_top;
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90.0f);
    slider_double("##top", &explorer.view.plot_top, 1e-2, 1e4, "outer %.3f", true);
    tooltip("The value at the outer circle (logarithmic slider; Ctrl+click to type).");
    return explorer.view.plot_top;
}

}  // namespace

void plot_section(Explorer& explorer, PlaneCurves* curves, float width, float height) {
    const Material* material = selected_material(explorer);
    if (!material || explorer.doc.scene.lights.empty()) {
        ImGui::TextUnformatted("(no light: nothing to plot)");
        return;
    }
    const float top_y = ImGui::GetCursorScreenPos().y;
    light_combo(explorer);
    const Light& light = explorer.doc.scene.lights[std::size_t(explorer.view.plotted_light)];
    ImGui::SameLine();
    const double top = scale_combo(explorer, curves, *material, light);
    const double incidence = incidence_at_target(light, explorer.doc.scene.camera);
    // A .brdf model has no CPU reference: PlaneCurves evaluates it on the GPU.
    auto curve_of = [&](const Material& m) {
        return curves ? curves->curve(m, light, incidence, explorer.doc.scene.background)
                                  : plane_curve(m, light, incidence, explorer.doc.scene.background);
    };
    const PlaneCurve curve = curve_of(*material);
    // The A/B split: B's curve beside A's (dashed), the same light and scale.
    std::optional<PlaneCurve> b;
    if (explorer.view.compare) b = curve_of(explorer.doc.material_b);
    // One curve many times the other's: log, so the smaller is not a few pixels tall (explore/plot_scale.h).
    const ShownScale shown = shown_scale(explorer.view.plot_scale, curve, b ? &*b : nullptr);
    double shown_top = explorer.view.plot_scale == RadialScale::lobe ? lobe_top(curve, b ? &*b : nullptr) : top;
    if (shown.scale == RadialScale::log && explorer.view.plot_scale != RadialScale::log)
        shown_top = std::max(1.0, lobe_top(curve, b ? &*b : nullptr));
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);  // the column's width, not the strip's
    ImGui::Text("object %d (%s%s), %.1f deg to N", explorer.view.selected_object, material->shown_name().c_str(),
                b ? ("; dashed: B " + explorer.doc.material_b.shown_name()).c_str() : "", incidence);
    ImGui::PushStyleColor(ImGuiCol_Text, curve.light_behind ? ImVec4(1, 0.8f, 0.3f, 1) : ImVec4(0.7f, 0.7f, 0.7f, 1));
    ImGui::TextWrapped("%s", curve.quantity().c_str());
    ImGui::PopStyleColor();
    if (!shown.why.empty()) ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "%s", shown.why.c_str());
    ImGui::PopTextWrapPos();
    // The half-disc plot is twice as wide as it is tall (polar_plot.h): the
    // room left under the text, less the scale's line under it.
    const float room = height - (ImGui::GetCursorScreenPos().y - top_y) - ImGui::GetTextLineHeightWithSpacing() - 4.0f;
    polar_plot(curve, shown.scale, shown_top, std::max(80.0f, std::min(2.0f * room, width)), b ? &*b : nullptr);
    tooltip("The red, green and blue value (CPU reference; the GPU for a .brdf model) for every view direction in the plane of the "
            "plotted light L (yellow) and N; dashed grey: the mirror direction R; dashed colours: material B "
            "(A/B split). Translucent objects: the displayed blend over the background colour.");
}

}  // namespace m3055::explore
