// Material parameters of the seeds' classic models (SPEC 5: Lambert,
// Half-Lambert variants, Oren-Nayar, Phong, Blinn-Phong, microfacet, Ward,
// Heidrich-Seidel), with the ranges the scene loader enforces.
#include "explore/widgets.h"

#include <imgui.h>

#include <glm/geometric.hpp>

namespace m3055::explore {

bool classic_material_editor(Material& material) {
    bool changed = false;
    changed |= color_edit("K_diff", &material.kd);
    changed |= color_edit("K_amb", &material.ka);
    if (has_specular(material.model)) changed |= color_edit("K_spec", &material.ks);
    changed |= color_edit("emission", &material.emission);
    switch (material.model) {
        case Model::oren_nayar:
            changed |= slider_double("sigma (rad)", &material.sigma, 0.0, 10.0, "%.3f", true);
            break;
        case Model::phong:
        case Model::blinn_phong:
        case Model::heidrich_seidel:
            changed |= slider_double("shininess", &material.shininess, 0.0, 10000.0, "%.1f", true);
            break;
        case Model::microfacet: {
            int distribution = static_cast<int>(material.distribution);
            if (ImGui::Combo("D", &distribution, "blinn_phong\0gaussian\0beckmann\0ggx\0")) {
                const bool was_exponent = material.distribution == Distribution::blinn_phong;
                material.distribution = static_cast<Distribution>(distribution);
                // Lobes hold an exponent n for blinn_phong, a roughness m otherwise.
                if (was_exponent != (material.distribution == Distribution::blinn_phong)) {
                    material.lobes = material.distribution == Distribution::blinn_phong
                                         ? std::vector<Lobe>{{1.0, 100.0}}
                                         : std::vector<Lobe>{{1.0, 0.3}};
                }
                changed = true;
            }
            int fresnel = static_cast<int>(material.fresnel);
            if (ImGui::Combo("F", &fresnel, "none\0schlick\0dielectric\0")) {
                material.fresnel = static_cast<Fresnel>(fresnel);
                changed = true;
            }
            changed |= slider_double("IOR", &material.ior, 1.0, 5.0);
            ImGui::TextUnformatted("lobes (w_j, m_j or n_j):");
            if (lobe_editor("microfacet_lobes", &material.lobes,
                            material.distribution != Distribution::blinn_phong, 1)) {
                for (Lobe& lobe : material.lobes) lobe.w = std::min(lobe.w, 1.0);  // loader: w in [0, 1]
                changed = true;
            }
            break;
        }
        case Model::ward:
            changed |= slider_double("alpha_x", &material.alpha_x, 0.001, 1.0, "%.3f", true);
            changed |= slider_double("alpha_y", &material.alpha_y, 0.001, 1.0, "%.3f", true);
            break;
        default: break;
    }
    if (material.model == Model::ward || material.model == Model::heidrich_seidel) {
        double a[3] = {material.axis.x, material.axis.y, material.axis.z};
        if (ImGui::DragScalarN("tangent axis", ImGuiDataType_Double, a, 3, 0.02f)) {
            const dvec3 axis(a[0], a[1], a[2]);
            if (glm::length(axis) > 1e-6) {  // the loader wants a non-zero direction, unit
                material.axis = glm::normalize(axis);
                changed = true;
            }
        }
    }
    return changed;
}

}  // namespace m3055::explore
