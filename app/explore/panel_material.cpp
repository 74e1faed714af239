// Material section: model, colour, the model's parameters with SPEC 7 ranges,
// and for the metals the eq. 14 read-out and rescale.
#include "explore/panels.h"

#include "explore/widgets.h"
#include "scene/presets.h"

#include <imgui.h>

#include <cmath>
#include <string>
#include <vector>

namespace m3055::explore {

bool classic_material_editor(Material& material);  // panel_classic.cpp

namespace {

const char* model_label(Model model) {
    switch (model) {
        case Model::highlight: return "highlight (eq. 4)";
        case Model::translucent: return "translucent (eq. 8)";
        case Model::metal: return "metal, Cook-Torrance (eq. 12)";
        case Model::metal_blinn: return "metal_blinn (eq. 15)";
        case Model::metal_phong: return "metal_phong (eq. 16)";
        default: return to_string(model);  // the classic models (SPEC 5)
    }
}

}  // namespace

// Used by the material section and by the compare section's material B.
bool material_editor(Material& material) {
    bool changed = false;
    if (ImGui::BeginCombo("model", model_label(material.model))) {
        for (Model model : all_models()) {
            if (ImGui::Selectable(model_label(model), model == material.model)) {
                set_model(material, model);
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    if (is_classic(material.model)) return changed | classic_material_editor(material);
    changed |= color_edit("colour C0", &material.color);
    const bool metal = uses_lobes(material.model);
    changed |= slider_double(metal ? "d (background)" : "d (environment)", &material.d, 0.0, 1.0);
    if (!metal) {
        changed |= slider_double("w (highlight)", &material.w, 0.0, 1.0);
        changed |= slider_double("m (size)", &material.m, 0.0, 10000.0, "%.2f", true);
    }
    if (material.model == Model::translucent) {
        changed |= slider_double("t_n (opacity)", &material.t_n, 0.0, 1.0);
        changed |= slider_double("t_p (falloff)", &material.t_p, 0.0, 10.0);
    }
    if (metal) {
        const bool beckmann = material.model == Model::metal;
        ImGui::TextUnformatted(beckmann ? "Beckmann lobes (w_j, m_j):" : "lobes (w_j, n_j):");
        changed |= lobe_editor("material_lobes", &material.lobes, beckmann, 1);
        const double peak = highlight_peak(material.model, material.d, material.lobes);
        ImGui::Text(beckmann ? "d + D(0) = d + sum w/m^2 = %.4f" : "d + sum w = %.4f", peak);
        ImGui::SameLine();
        ImGui::TextColored(std::abs(peak - 1.0) < 5e-4 ? ImVec4(0.5f, 1, 0.5f, 1) : ImVec4(1, 0.8f, 0.3f, 1),
                           std::abs(peak - 1.0) < 5e-4 ? "(eq. 14 holds)" : "(eq. 14 wants 1)");
        if (ImGui::Button("Rescale weights to eq. 14")) {
            changed |= rescale_to_eq14(material.model, material.d, material.lobes);
        }
        if (ImGui::IsItemHovered()) {
            ImGui::SetTooltip("Scales every w_j by one factor so the highlight centre is C0:\n"
                              "d + sum_j w_j / m_j^2 = 1 (eq. 14).");
        }
    }
    return changed;
}

void material_section(ExplorerState& state) {
    Material* material = selected_material(state);
    if (!material) return;
    ImGui::Text("object %d of %zu (choose in Objects)", state.selected_object,
                state.scene.objects.size());
    if (material_editor(*material)) state.changed();
}

}  // namespace m3055::explore
