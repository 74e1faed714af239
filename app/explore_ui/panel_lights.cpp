// Lights section: presets, then one collapsible block per light.
#include "explore_ui/panels.h"

#include "explore_ui/light_widgets.h"
#include "explore_ui/narrow_panel.h"
#include "explore_ui/widgets.h"
#include "io/message_text.h"
#include "scene/area_light.h"
#include "scene/light_colour.h"

#include <imgui.h>
#include <imgui_stdlib.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace m3055::explore {

namespace {

const char* const kIntensityHelp = "a_l, the light's intensity, in [0, 10] (spec section 3: a_l multiplies its term); "
                                   "logarithmic, 0.001 ... 10 (0 at the left end); Shift drags finely, Ctrl+click types";

// The scene format's light "name": what is typed is kept to what the format
// allows (explore/explorer.h), and applied on Enter only (grading rules find
// lights by name: a Tab or a stray click must not rename one); Esc restores it.
bool name_field(Light& light) {
    std::string name;
    if (!typed_field(field("name").c_str(), light.name, &name, true)) return false;
    name = valid_light_name(name);
    if (name == light.name) return false;
    light.name = name;
    return true;
}

// The light's colour (docs/spec.md#71-spectral-lights): RGB, a black body on
// the Planckian locus (a kelvin slider) or a CIE illuminant, with a swatch of
// the spectrum's colour (its RGB at luminance 1, scaled so the largest
// channel is 1: a channel may exceed 1). `error`: why a spectrum could not be
// made (colord-data missing).
bool colour_editor(Light& light, std::string& error) {
    const LightColourSource source = colour_source(light);
    int from = static_cast<int>(source);
    bool changed = false;
    if (ImGui::Combo(field("colour from").c_str(), &from, "RGB\0black body (kelvin)\0CIE illuminant\0") &&
        from != static_cast<int>(source)) {
        const auto chosen = static_cast<LightColourSource>(from);
        if (chosen == LightColourSource::rgb) {
            set_rgb_colour(light, light.color / std::max({light.color.r, light.color.g, light.color.b, 1.0}));
            changed = true;
        } else if (chosen == LightColourSource::temperature) {
            changed = set_temperature(light, 6500.0, &error);
        } else {
            changed = set_illuminant(light, "D65", &error);
        }
    }
    tooltip("RGB: c_l itself. Black body: Planck's law at a temperature; CIE illuminant: a standard spectrum "
            "(A tungsten, D65 daylight, F fluorescent ...). A spectrum's colour is its integral against the CIE "
            "1931 observer, as linear sRGB at luminance 1 (spec section 7.1).");
    if (source == LightColourSource::rgb) {
        dvec3 rgb = light.color;
        if (color_edit("colour c", &rgb)) {
            set_rgb_colour(light, rgb);
            changed = true;
        }
        tooltip("c_l, the light's colour: RGB, each in [0, 1] (spec section 3 notation)");
        return changed;
    }
    if (source == LightColourSource::temperature) {
        double kelvin = light.temperature_k;
        if (slider_double("temperature", &kelvin, kMinLightKelvin, kMaxLightKelvin, "%.0f K", true,
                          std::log10(kMaxLightKelvin / kMinLightKelvin)) &&
            set_temperature(light, std::round(kelvin), &error))
            changed = true;
        tooltip("The black body's temperature, 1000 to 40 000 K (logarithmic; Ctrl+click types): candle ~1900, "
                "tungsten 3200, daylight 5600-6500, blue sky 10 000+");
    } else {
        const auto& names = light_illuminant_names();
        if (ImGui::BeginCombo(field("illuminant").c_str(), light.illuminant.c_str())) {
            for (const std::string& name : names)
                if (ImGui::Selectable(name.c_str(), name == light.illuminant) && name != light.illuminant)
                    changed |= set_illuminant(light, name, &error);
            ImGui::EndCombo();
        }
        tooltip("A CIE standard illuminant as colord-data ships it: A (tungsten, 2856 K), D50/D65 (daylight), "
                "F1-F12 (fluorescent) ...");
    }
    const double top = std::max({light.color.r, light.color.g, light.color.b});
    const ImVec4 swatch(float(light.color.r / top), float(light.color.g / top), float(light.color.b / top), 1.0f);
    ImGui::ColorButton("##swatch", swatch, ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoAlpha,
                       ImVec2(ImGui::GetFrameHeight() * 2.0f, ImGui::GetFrameHeight()));
    ImGui::SameLine();
    ImGui::PushTextWrapPos(0.0f);
    ImGui::Text("RGB %.3f %.3f %.3f", light.color.r, light.color.g, light.color.b);
    ImGui::PopTextWrapPos();
    tooltip("the spectrum's colour as linear sRGB at luminance Y = 1 (a channel may exceed 1; the swatch is "
            "scaled so the largest is 1)");
    return changed;
}

// A light made another type keeps its colour, intensity and name; an area
// light gets a place and a facing it can be seen from: where a directional
// light came from, 4 units out, facing the origin.
void change_type(Light& light, LightType type) {
    const bool had_position = light.type != LightType::directional && light.type != LightType::sky;
    if (!had_position) light.position = 4.0 * light.direction;
    light.type = type;
    if (type == LightType::rect || type == LightType::disk) {
        const double distance = glm::length(light.position);
        light.normal = distance > 1e-9 ? -light.position / distance : dvec3(0.0, -1.0, 0.0);
        light.up = default_rect_up(light.normal);
    }
    if (type == LightType::directional && glm::length(light.position) > 1e-9)
        light.direction = glm::normalize(light.position);
}

// Where a rect or disk is and which way it faces, its size; the sky's up.
bool area_light_fields(Light& light) {
    bool changed = false;
    if (light.type == LightType::sky) {
        ImGui::TextUnformatted("up (the sky's zenith):");
        changed |= light_sphere_widget("##up", &light.up, 30.0f);
        changed |= slider_double("intensity a", &light.intensity, 0.0, 10.0, "%.3f", true, kIntensityDecades);
        tooltip("a_l: radiance a c / pi from every direction above the horizon of up; a unit sky lights an upward "
                "white Lambert plane as a unit light from the zenith does");
        return changed;
    }
    double p[3] = {light.position.x, light.position.y, light.position.z};
    if (ImGui::DragScalarN(field("position").c_str(), ImGuiDataType_Double, p, 3, 0.05f)) {
        light.position = {p[0], p[1], p[2]};
        changed = true;
    }
    tooltip("the emitter's centre, in scene units");
    ImGui::TextUnformatted("faces (the emitting side's normal):");
    if (light_sphere_widget("##normal", &light.normal, 30.0f)) {
        if (light.type == LightType::rect && glm::length(glm::cross(light.normal, light.up)) < 1e-3)
            light.up = default_rect_up(light.normal);  // up parallel to the normal is refused
        changed = true;
    }
    if (ImGui::SmallButton("face the origin") && glm::length(light.position) > 1e-9) {
        light.normal = -glm::normalize(light.position);
        if (light.type == LightType::rect) light.up = default_rect_up(light.normal);
        changed = true;
    }
    tooltip("Turns the emitter to face the scene's origin from where it is.");
    if (light.type == LightType::rect) {
        changed |= slider_double("width", &light.size[0], 0.01, 100.0, "%.3f", true);
        tooltip("size[0], the side along normal x up, in scene units (logarithmic)");
        changed |= slider_double("height", &light.size[1], 0.01, 100.0, "%.3f", true);
        tooltip("size[1], the side along up, in scene units (logarithmic)");
    } else {
        changed |= slider_double("radius", &light.radius, 0.01, 100.0, "%.3f", true);
        tooltip("the disk's radius, in scene units (logarithmic)");
    }
    changed |= slider_double("intensity a", &light.intensity, 0.0, 10.0, "%.3f", true, kIntensityDecades);
    tooltip("a_l: far away the emitter is a point light of intensity a cos(theta_e) with 1/d^2 falloff; its "
            "radiance is a c / area (docs/spec.md section 7.5)");
    return changed;
}

// Edits `light` (a copy of light `index`; `material` the selected object's, for the metals' own lobes).
bool light_editor(Light& light, int index, const Material* material, std::string& error) {
    bool changed = name_field(light);
    tooltip("Optional: \"key\", \"fill\", \"back\" (as the three-point presets name them; the key-to-fill "
            "ratio and grading rules use them) or any text up to 64 bytes. Enter applies it, Esc restores it. "
            "Saved with the scene.");
    changed |= checkbox("enabled", &light.enabled);
    tooltip("Off: the light adds nothing but stays in the scene (saved as \"enabled\": false).");
    int type = static_cast<int>(light.type);
    if (!narrow_panel()) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(120);
    }
    const bool type_changed =
        ImGui::Combo(field("type").c_str(), &type, "directional\0point\0spot\0rect\0disk\0sky\0");
    tooltip("directional (the paper's lights), point or spot (the lecture's, with attenuation), or a light with "
            "an area: a rect or disk emitting from one side (a softbox, a window), or the whole sky "
            "(docs/spec.md section 7.5)");
    if (type_changed) {
        change_type(light, static_cast<LightType>(type));
        changed = true;
    }
    static double azimuth_memory[kMaxLights] = {};
    if (is_area_light(light.type)) {
        changed |= area_light_fields(light);
    } else if (light.type == LightType::directional) {
        changed |= light_sphere_widget("##sphere", &light.direction, 38.0f);
        if (!narrow_panel()) ImGui::SameLine();  // narrow: the sliders under the sphere, whole width
        ImGui::BeginGroup();
        ImGui::PushItemWidth(150);
        changed |= light_angle_sliders(&light.direction, &azimuth_memory[index % kMaxLights]);
        changed |= slider_double("intensity a", &light.intensity, 0.0, 10.0, "%.3f", true, kIntensityDecades);
        tooltip(kIntensityHelp);
        ImGui::PopItemWidth();
        ImGui::EndGroup();
    } else {
        double p[3] = {light.position.x, light.position.y, light.position.z};
        if (ImGui::DragScalarN(field("position").c_str(), ImGuiDataType_Double, p, 3, 0.05f)) {
            light.position = {p[0], p[1], p[2]};
            changed = true;
        }
        tooltip("where the light is, in scene units (docs/spec.md section 7)");
        changed |= slider_double("intensity a", &light.intensity, 0.0, 10.0, "%.3f", true, kIntensityDecades);
        tooltip(kIntensityHelp);
        changed |= slider_double("S_c", &light.att_constant, 0.0, 10.0, "%.3f", true, kIntensityDecades);
        tooltip("constant term of the attenuation 1/(S_c + S_l r + S_q r^2), in [0, 10] (the lecture's equation, spec section 4)");
        changed |= slider_double("S_l", &light.att_linear, 0.0, 10.0, "%.3f", true, kIntensityDecades);
        tooltip("linear term of the attenuation 1/(S_c + S_l r + S_q r^2), in [0, 10] (spec section 4)");
        changed |= slider_double("S_q", &light.att_quadratic, 0.0, 10.0, "%.3f", true, kIntensityDecades);
        tooltip("quadratic term of the attenuation 1/(S_c + S_l r + S_q r^2), in [0, 10] (spec section 4)");
        if (light.type == LightType::spot) {
            ImGui::TextUnformatted("spot direction:");
            changed |= light_sphere_widget("##spot", &light.spot_direction, 30.0f);
            changed |= slider_double("spot exponent", &light.spot_exponent, 0.0, 1000.0, "%.1f", true);
            tooltip("the spot's falloff (cos of the angle to its axis)^exponent, in [0, 1000] (spec section 4; logarithmic)");
        }
    }
    changed |= colour_editor(light, error);
    // Last, so that the rows above stay where they were before shadows existed.
    changed |= checkbox("shadow", &light.shadow);
    tooltip("On: objects block this light (hard shadows from directional, point and spot lights, soft from rect, "
            "disk and sky). The explorer's display previews area lights at their centres, one shadow ray each; "
            "a screenshot and m3055 render take 8 x 8 (docs/lights.md).");

    // Per-light lobes (Fig. 11): only meaningful when the selected material is a metal.
    if (material && material->model().light_lobes) {
        const LobeKind kind = *material->model().light_lobes;
        bool own = !light.lobes.empty() && light.lobe_kind == kind;
        if (checkbox("own lobes (replace the material's for this light)", &own)) {
            light.lobes = own ? material->lobes().to_vector() : std::vector<Lobe>{};
            light.lobe_kind = kind;
            changed = true;
        }
        tooltip("On: this light uses its own lobes instead of the material's (as in the paper's Fig. 11); "
                "off: the material's.");
        const LobeForm& form = material->model().param("lobes").form_for(*material);
        if (own) changed |= lobe_editor("light_lobes", &light.lobes, form, 1);
    }
    return changed;
}

}  // namespace

void lights_section(Explorer& explorer) {
    ImGui::TextUnformatted("presets:");
    int column = 0;
    for (LightPreset preset : kAllLightPresets) {
        // Two columns; one on a narrow panel (the labels are longer than half of it).
        const bool two = !narrow_panel();
        if (two && column++ % 2) ImGui::SameLine();
        const float width = ImGui::GetContentRegionAvail().x * (two && column % 2 ? 0.49f : 1.0f);
        if (ImGui::Button(preset_label(preset), ImVec2(width, 0))) {
            explorer.commands.push(command::ApplyLightPreset{preset});
        }
        tooltip("Replaces all lights with this preset (undoable with Ctrl+Z).");
    }
    auto& lights = explorer.doc.scene.lights;
    for (int i = 0; i < static_cast<int>(lights.size()); ++i) {
        ImGui::PushID(i);
        const std::string title = "light " + std::to_string(i) +
                                  (lights[i].name.empty() ? "" : " \"" + lights[i].name + "\"") +
                                  // the type on a narrow panel only in the editor (it would run under "remove")
                                  (narrow_panel() ? (lights[i].enabled ? "" : " (off)")
                                                  : " (" + std::string(to_string(lights[i].type)) +
                                                        (lights[i].enabled ? "" : ", off") + ")") +
                                  "###light";
        ImGui::SetNextItemOpen(i == 0, ImGuiCond_Once);
        const bool open = ImGui::TreeNode(title.c_str());
        if (ImGui::IsItemClicked()) explorer.view.selected_light = i;
        ImGui::SameLine(ImGui::GetContentRegionMax().x - 60);
        const bool removed = ImGui::SmallButton("remove");
        tooltip("Removes this light (undoable).");
        if (open) {
            Light edited = lights[std::size_t(i)];
            if (!removed && light_editor(edited, i, selected_material(explorer), explorer.session.messages.error)) {
                explorer.commands.push(command::SetLight{i, edited});
                explorer.view.selected_light = i;
            }
            ImGui::TreePop();
        }
        ImGui::PopID();
        if (removed) {
            explorer.commands.push(command::RemoveLight{i});
            break;
        }
    }
    ImGui::BeginDisabled(static_cast<int>(lights.size()) >= kMaxExplorerLights);
    if (ImGui::Button("+ add light")) explorer.commands.push(command::AddLight{});
    tooltip("Adds a copy of the single-key light, at most 8 (undoable).");
    ImGui::EndDisabled();
    same_line_if_fits(ImGui::CalcTextSize("8 of 8").x);
    ImGui::TextDisabled("%zu of %d", lights.size(), kMaxExplorerLights);
    if (!lights.empty()) light_plot(explorer);
}

}  // namespace m3055::explore
