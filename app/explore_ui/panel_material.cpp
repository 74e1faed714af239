// Material section: the model selector and one widget per parameter of the
// model, all from the model table (renderer/models/builtin_models.cpp):
// labels, ranges, logarithmic sliders and tooltips (meaning, range, citation).
// The metal family adds the eq. 14 read-out and rescale.
#include "explore_ui/panels.h"

#include "explore/material_fields.h"
#include "explore_ui/narrow_panel.h"
#include "explore_ui/widgets.h"
#include "models/model_table.h"
#include "scene/presets.h"

#include <imgui.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace m3055::explore {

namespace {

// "meaning\nrange (citation)" for a parameter's tooltip.
std::string param_tooltip(const ParamSpec& param) {
    std::string text = param.help;
    if (param.kind == ParamKind::number) text += "\n" + param.range.text();
    if (param.kind == ParamKind::colour) text += "\nRGB, each in [0, 1]";
    if (!param.cite.empty()) text += " (" + param.cite + ")";
    return text;
}

void show_tooltip(const ParamSpec& param) {
    if (tooltip_due()) ImGui::SetTooltip("%s", param_tooltip(param).c_str());
}

// A choice; when a lobe list's form follows it and the key changes, the
// lobes start again from the new form's defaults (m and n mean different things).
// The words the UI shows for choice i: its label in the table, else the choice itself.
const std::string& choice_label(const ParamSpec& param, int i) {
    const std::size_t at = std::size_t(i);
    return at < param.choice_labels.size() && !param.choice_labels[at].empty() ? param.choice_labels[at] : param.choices[at];
}

bool choice_widget(Material& material, const ParamSpec& param) {
    int index = material.choice(param.name);
    if (!ImGui::BeginCombo(field(param.label).c_str(), choice_label(param, index).c_str(), combo_flags())) {
        show_tooltip(param);
        return false;
    }
    bool changed = false;
    for (int i = 0; i < static_cast<int>(param.choices.size()); ++i) {
        if (!ImGui::Selectable(choice_label(param, i).c_str(), i == index)) continue;
        const Material before = material;
        material.set_choice(param.name, i);
        carry_replaced_colour(before, material, param);
        for (const ParamSpec& other : material.model().params) {
            if (other.form_from == param.name && other.form_for(material).key != other.form_for(before).key)
                material.set_lobes(other.name, other.form_for(material).fallback);
        }
        changed = true;
    }
    ImGui::EndCombo();
    return changed;
}

bool direction_widget(Material& material, const ParamSpec& param) {
    const dvec3 v = material.vec3(param.name);
    double a[3] = {v.x, v.y, v.z};
    if (!ImGui::DragScalarN(field(param.label).c_str(), ImGuiDataType_Double, a, 3, 0.02f)) return false;
    const dvec3 axis(a[0], a[1], a[2]);
    if (glm::length(axis) <= 1e-6) return false;  // the loader wants a non-zero direction, unit
    material.set_vec3(param.name, glm::normalize(axis));
    return true;
}

bool param_widget(Material& material, const ParamSpec& param) {
    bool changed = false;
    switch (param.kind) {
        case ParamKind::number: {
            double value = material.number(param.name);
            changed = slider_double(param.label.c_str(), &value, param.range.lo, param.range.hi, param.format.c_str(),
                                    param.log_slider);
            if (changed) material.set_number(param.name, value);
            break;
        }
        case ParamKind::colour: {
            dvec3 colour = material.vec3(param.name);
            changed = color_edit(param.label.c_str(), &colour);
            if (changed) material.set_vec3(param.name, colour);
            break;
        }
        case ParamKind::direction: changed = direction_widget(material, param); break;
        case ParamKind::choice: return choice_widget(material, param);
        case ParamKind::flag: {
            bool on = material.flag(param.name);
            changed = checkbox(param.label.c_str(), &on);
            if (changed) material.set_flag(param.name, on);
            break;
        }
        case ParamKind::lobes: {
            ImGui::TextUnformatted((param.label + ":").c_str());
            show_tooltip(param);
            std::vector<Lobe> lobes = material.lobes(param.name).to_vector();
            changed = lobe_editor(param.name.c_str(), &lobes, param.form_for(material), 1);
            if (changed) material.set_lobes(param.name, lobes);
            return changed;
        }
    }
    show_tooltip(param);
    return changed;
}

// The metals' eq. 14: the highlight centre is C0 when d + D(0) = 1. True
// when the button rescaled the weights.
bool eq14_readout(Material& material) {
    const bool beckmann = material.model().param("lobes").form_for(material).key == "m";
    const double peak = highlight_peak(material);
    const bool holds = std::abs(peak - 1.0) < 5e-4;
    if (narrow_panel()) {  // the sum on a line, its value and verdict on the next
        ImGui::TextUnformatted(beckmann ? "d + D(0) = d + sum w/m^2" : "d + sum w");
        ImGui::Text("= %.4f", peak);
    } else {
        ImGui::Text(beckmann ? "d + D(0) = d + sum w/m^2 = %.4f" : "d + sum w = %.4f", peak);
    }
    same_line_if_fits(ImGui::CalcTextSize("(eq. 14 wants 1)").x);
    ImGui::TextColored(holds ? ImVec4(0.5f, 1, 0.5f, 1) : ImVec4(1, 0.8f, 0.3f, 1),
                       holds ? "(eq. 14 holds)" : "(eq. 14 wants 1)");
    const bool changed = ImGui::Button("Rescale weights to eq. 14") && rescale_to_eq14(material);
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("Scales every w_j by one factor so the highlight centre is C0:\n"
                          "d + sum_j w_j / m_j^2 = 1 (eq. 14).");
    }
    return changed;
}

}  // namespace

// Edits `material` (a copy: the caller hands it to an operation, with
// `action` naming a button's edit, else ""). Used by the material section and
// by the compare section's material B.
bool material_editor(Material& material, std::string& action) {
    bool changed = false;
    if (ImGui::BeginCombo(field("model").c_str(), material.model().label.c_str(), combo_flags())) {
        for (const ModelSpec* model : all_models()) {
            if (ImGui::Selectable(model->label.c_str(), model == &material.model())) {
                material = with_model(material, *model);
                changed = true;
            }
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("%s\n%s", model->summary.c_str(), model->citation.c_str());
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s\n%s", material.model().summary.c_str(), material.model().citation.c_str());
    for (const ParamSpec& param : material.model().params) {
        ImGui::PushID(param.name.c_str());
        // A colour a conductor or a color_spectrum stands in for: shown, disabled, and why (explore/material_fields.h).
        const std::string inert = inert_reason(material, param);
        ImGui::BeginDisabled(!inert.empty());
        changed |= param_widget(material, param);
        ImGui::EndDisabled();
        if (!inert.empty()) {
            hint(inert.c_str());
            tooltip(inert_detail(material, param));
            if (material.colour_spectrum() && !param.spectrum_key.empty()) {
                if (ImGui::SmallButton("use an RGB colour instead")) {
                    material.set_colour_spectrum(nullptr);  // the field keeps the spectrum's D65 colour
                    changed = true;
                }
                tooltip("Drops the color_spectrum; the colour stays its colour under D65 (undoable).");
            }
        }
        ImGui::PopID();
    }
    if (material.model().family == Family::metal && eq14_readout(material)) {
        action = kEq14Action;
        changed = true;
    }
    return changed;
}

namespace {

// A mesh's materials from its model file, by the file's names: which one the panel edits.
void model_file_material_combo(Explorer& explorer, int group) {
    const Object& object = explorer.doc.scene.objects[std::size_t(explorer.view.selected_object)];
    auto label = [&](std::size_t i) {
        const GroupMaterial& g = object.groups[i];
        return (g.name.empty() ? "(unnamed)" : g.name) + (g.overridden ? "  (edited)" : "");
    };
    if (ImGui::BeginCombo("file material", label(std::size_t(group)).c_str())) {
        for (std::size_t i = 0; i < object.groups.size(); ++i)
            if (ImGui::Selectable(label(i).c_str(), int(i) == group)) explorer.view.selected_group = int(i);
        ImGui::EndCombo();
    }
    tooltip("The model file's materials by their names; an edited one is saved in the scene's \"materials\".");
}

}  // namespace

void material_section(Explorer& explorer) {
    Material* material = selected_material(explorer);
    if (!material) return;
    ImGui::TextWrapped("object %d of %zu (choose in Objects)", explorer.view.selected_object,
                explorer.doc.scene.objects.size());
    const int group = selected_group(explorer);
    if (group >= 0) model_file_material_combo(explorer, group);
    brdf_material_note(explorer, *material);
    Material edited = *material;
    std::string action;
    if (material_editor(edited, action))
        explorer.commands.push(command::SetMaterial{explorer.view.selected_object, edited, action, group});
    else if (material->model().family == Family::metal) {
        // docs/spec.md#72-measured-metals: what assumption 3 costs, side by side.
        if (ImGui::Button("A/B: F(\u03bb, 0) vs full eq. 19")) explorer.commands.push(command::CompareFresnel{});
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The split on: A with the paper's F(lambda, 0) (assumption 3), B with the\n"
                              "full eq. 19 for the metal's complex index (gold if it names no conductor).");
    }
}

}  // namespace m3055::explore
