#include "scene/presets.h"

#include "scene/light_direction.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace m3055 {

namespace {

Light directional(double azimuth_deg, double elevation_deg, double intensity,
                  dvec3 color = {1.0, 1.0, 1.0}) {
    Light light;
    light.type = LightType::directional;
    light.direction = direction_from_angles({azimuth_deg, elevation_deg});
    light.intensity = intensity;
    light.color = color;
    return light;
}

// Classic three-point lighting seen from the camera: the key 45 degrees to the
// right and above, a weaker fill low on the other side to soften the key's
// shadow side, and a back (rim) light behind and above that outlines the
// silhouette.
std::vector<Light> three_point(dvec3 key_color) {
    return {directional(45.0, 35.0, 1.0, key_color),  // key
            directional(-60.0, 10.0, 0.4),             // fill
            directional(160.0, 45.0, 0.7)};            // back
}

}  // namespace

const char* preset_name(LightPreset preset) {
    switch (preset) {
        case LightPreset::single_key: return "single_key";
        case LightPreset::three_point_white: return "three_point_white";
        case LightPreset::three_point_warm: return "three_point_warm";
        case LightPreset::three_point_cool: return "three_point_cool";
        case LightPreset::paper_main_secondary: return "paper_main_secondary";
    }
    return "?";
}

const char* preset_label(LightPreset preset) {
    switch (preset) {
        case LightPreset::single_key: return "Single key";
        case LightPreset::three_point_white: return "3-point, white key";
        case LightPreset::three_point_warm: return "3-point, warm key";
        case LightPreset::three_point_cool: return "3-point, cool key";
        case LightPreset::paper_main_secondary: return "Paper: main + secondary";
    }
    return "?";
}

bool parse_light_preset(const std::string& name, LightPreset* preset) {
    for (LightPreset p : kAllLightPresets) {
        if (name == preset_name(p)) {
            *preset = p;
            return true;
        }
    }
    return false;
}

std::vector<Light> light_preset(LightPreset preset) {
    switch (preset) {
        case LightPreset::single_key: return {directional(45.0, 35.0, 1.0)};
        case LightPreset::three_point_white: return three_point({1.0, 1.0, 1.0});
        case LightPreset::three_point_warm:
            return three_point({kWarmKey[0], kWarmKey[1], kWarmKey[2]});
        case LightPreset::three_point_cool:
            return three_point({kCoolKey[0], kCoolKey[1], kCoolKey[2]});
        case LightPreset::paper_main_secondary: {
            // Main "upper right": the SPEC 7 example direction (1, 1, 1).
            Light main;
            main.direction = glm::normalize(dvec3(1.0, 1.0, 1.0));
            // Secondary "left and below", in front of the object.
            Light secondary;
            secondary.direction = glm::normalize(dvec3(-1.0, -0.6, 0.6));  // as scenes/fig11.json
            secondary.intensity = 0.7;
            return {main, secondary};
        }
    }
    return {};
}

double highlight_peak(Model model, double d, const std::vector<Lobe>& lobes) {
    if (!uses_lobes(model)) return d;
    double sum = 0.0;
    for (const Lobe& lobe : lobes) {
        // eq. 13 at alpha = 0: delta(m, 0) = 1 / m^2; exponent lobes peak at 1.
        sum += model == Model::metal ? lobe.w / (lobe.m * lobe.m) : lobe.w;
    }
    return d + sum;
}

bool rescale_to_eq14(Model model, double d, std::vector<Lobe>& lobes) {
    if (!uses_lobes(model) || d >= 1.0) return false;
    const double specular = highlight_peak(model, d, lobes) - d;
    if (!(specular > 0.0) || !std::isfinite(specular)) return false;
    const double factor = (1.0 - d) / specular;  // eq. 14: d + factor * specular = 1
    for (const Lobe& lobe : lobes) {
        if (lobe.w * factor > 100.0) return false;  // SPEC 7: lobe weights in [0, 100]
    }
    for (Lobe& lobe : lobes) lobe.w *= factor;
    return true;
}

Scene default_scene() {
    Scene scene;  // scene.h defaults are the SPEC 7 example's display and camera
    scene.lights = {Light{}};
    scene.lights[0].direction = glm::normalize(dvec3(1.0, 1.0, 1.0));
    Object sphere;
    sphere.material.model = Model::highlight;
    sphere.material.color = {0.8, 0.2, 0.2};
    sphere.material.d = 0.5;
    sphere.material.w = 1.0;
    sphere.material.m = 10.0;
    scene.objects = {sphere};
    return scene;
}

std::vector<Lobe> default_lobes(Model model) {
    switch (model) {
        case Model::metal: return {{0.013, 0.2}, {0.1, 0.4}};  // Fig. 10
        case Model::metal_blinn: return {{0.95, 13.0}};         // Fig. 12's n = 13
        case Model::metal_phong: return {{0.19, 20.0}, {0.76, 3.0}};  // scenes/fig13.json
        default: return {};
    }
}

}  // namespace m3055
