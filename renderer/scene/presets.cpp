#include "scene/presets.h"

#include "models/model_table.h"
#include "scene/light_colour.h"
#include "scene/light_direction.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace m3055 {

namespace {

Light directional(const char* name, double azimuth_deg, double elevation_deg, double intensity,
                  dvec3 color = {1.0, 1.0, 1.0}) {
    Light light;
    light.name = name;
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
    return {directional("key", 45.0, 35.0, 1.0, key_color), directional("fill", -60.0, 10.0, 0.4),
            directional("back", 160.0, 45.0, 0.7)};
}

}  // namespace

const char* preset_name(LightPreset preset) {
    switch (preset) {
        case LightPreset::single_key: return "single_key";
        case LightPreset::three_point_white: return "three_point_white";
        case LightPreset::three_point_warm: return "three_point_warm";
        case LightPreset::three_point_cool: return "three_point_cool";
        case LightPreset::three_point_studio: return "three_point_studio";
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
        case LightPreset::three_point_studio: return "studio: 3200 K key, 5600 K fill";
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
        case LightPreset::single_key: return {directional("key", 45.0, 35.0, 1.0)};
        case LightPreset::three_point_white: return three_point({1.0, 1.0, 1.0});
        case LightPreset::three_point_warm:
            return three_point({kWarmKey[0], kWarmKey[1], kWarmKey[2]});
        case LightPreset::three_point_cool:
            return three_point({kCoolKey[0], kCoolKey[1], kCoolKey[2]});
        case LightPreset::three_point_studio: {
            // Tungsten key, daylight fill and back: a film studio's mix.
            std::vector<Light> lights = three_point({1.0, 1.0, 1.0});
            std::string error;
            for (Light& light : lights)
                if (!set_temperature(light, light.name == "key" ? 3200.0 : 5600.0, &error))
                    throw std::runtime_error("studio lights: " + error);
            return lights;
        }
        case LightPreset::paper_main_secondary: {
            // Main "upper right": the docs/spec.md#7-scene-files example direction (1, 1, 1).
            Light main;
            main.name = "main";
            main.direction = glm::normalize(dvec3(1.0, 1.0, 1.0));
            // Secondary "left and below", in front of the object.
            Light secondary;
            secondary.name = "secondary";
            secondary.direction = glm::normalize(dvec3(-1.0, -0.6, 0.6));  // as scenes/fig11.json
            secondary.intensity = 0.7;
            return {main, secondary};
        }
    }
    return {};
}

namespace {
bool is_metal(const Material& material) { return material.model().family == Family::metal; }
}  // namespace

double highlight_peak(const Material& material) {
    const double d = material.has("d") ? material.number("d") : 0.0;
    if (!is_metal(material)) return d;
    // eq. 13 at alpha = 0: delta(m, 0) = 1 / m^2; exponent lobes peak at 1.
    const bool beckmann = material.model().param("lobes").form_for(material).key == "m";
    double sum = 0.0;
    for (const Lobe& lobe : material.lobes()) sum += beckmann ? lobe.w / (lobe.m * lobe.m) : lobe.w;
    return d + sum;
}

bool rescale_to_eq14(Material& material) {
    if (!is_metal(material)) return false;
    const double d = material.number("d");
    if (d >= 1.0) return false;
    const double specular = highlight_peak(material) - d;
    if (!(specular > 0.0) || !std::isfinite(specular)) return false;
    const double factor = (1.0 - d) / specular;  // eq. 14: d + factor * specular = 1
    const Range& weights = material.model().param("lobes").form_for(material).weight;
    std::vector<Lobe> lobes = material.lobes().to_vector();
    for (Lobe& lobe : lobes) {
        lobe.w *= factor;
        if (!weights.contains(lobe.w)) return false;
    }
    material.set_lobes(lobes);
    return true;
}

Scene default_scene() {
    Scene scene;  // scene.h defaults are the docs/spec.md#7-scene-files example's display and camera
    scene.lights = {Light{}};
    scene.lights[0].direction = glm::normalize(dvec3(1.0, 1.0, 1.0));
    Object sphere;
    sphere.material = Material::of("highlight");
    sphere.material.set_vec3("color", {0.8, 0.2, 0.2});
    sphere.material.set_number("d", 0.5);
    sphere.material.set_number("w", 1.0);
    sphere.material.set_number("m", 10.0);
    scene.objects = {sphere};
    return scene;
}

}  // namespace m3055
