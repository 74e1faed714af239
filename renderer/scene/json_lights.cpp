#include "scene/json_lights.h"

#include "io/message_text.h"
#include "models/model_table.h"
#include "scene/area_light.h"
#include "spectral/blackbody.h"
#include "spectral/cie_data.h"
#include "spectral/colorimetry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <stdexcept>

namespace m3055::scene_json {

namespace {

const Range kSpotExponent = closed(0.0, 10000.0);
// Rect sides and disk radii: a lower bound keeps a_l / area finite in float (the GPU) and double.
const Range kEmitterLength = closed(1e-6, 1e6);

const std::vector<std::string> kLightTypes = {"directional", "point", "spot", "rect", "disk", "sky"};

// The keys each light type reads besides those every light has.
std::vector<std::string> light_keys(LightType type) {
    switch (type) {
        case LightType::directional: return {"direction", "ambient"};
        case LightType::point: return {"position", "attenuation", "ambient"};
        case LightType::spot: return {"position", "attenuation", "spot_direction", "spot_exponent", "ambient"};
        case LightType::rect: return {"position", "normal", "up", "size"};
        case LightType::disk: return {"position", "normal", "radius"};
        case LightType::sky: return {"up"};
    }
    return {};
}

// For a key that other light types read: "only for point and spot lights"; else "".
std::string light_key_owners(const std::string& key) {
    std::vector<std::string> found;
    for (std::size_t t = 0; t < kLightTypes.size(); ++t)
        for (const std::string& k : light_keys(static_cast<LightType>(t)))
            if (k == key) found.push_back(kLightTypes[t]);
    if (found.empty()) return {};
    std::string text = "only for " + found[0];
    for (std::size_t i = 1; i < found.size(); ++i) text += (i + 1 == found.size() ? " and " : ", ") + found[i];
    return text + " lights";
}

// A light's own lobes replace the material's for the models that read them
// (ModelSpec::light_lobes), so they have those models' ranges.
const LobeForm& light_lobe_form(LobeKind kind) {
    for (const ModelSpec& spec : model_table().models())
        if (spec.light_lobes == kind) return spec.param("lobes").forms.at(0);
    throw std::logic_error("no model of the table reads light lobes of this kind");
}

// A light's own lobes: all Beckmann {"w","m"} or all exponent {"w","n"}.
void read_light_lobes(const Node& node, Light& light) {
    const std::size_t count = node.array_size(1, kMaxLobes, "1 to 4 lobes");
    for (std::size_t i = 0; i < count; ++i) {
        const Node entry = node.at(i);
        entry.expect_object();
        entry.check_keys({"w", "m", "n"});
        if (entry.has("m") == entry.has("n")) entry.fail("must have exactly one of \"m\" and \"n\"");
        const LobeKind kind = entry.has("m") ? LobeKind::beckmann : LobeKind::exponent;
        const std::string key = kind == LobeKind::beckmann ? "m" : "n";
        if (i == 0) {
            light.lobe_kind = kind;
        } else if (kind != light.lobe_kind) {
            entry.child(key).fail("all lobes of a light must use the same key (lobes[0] uses \"" +
                                  std::string(kind == LobeKind::beckmann ? "n" : "m") + "\")");
        }
        const LobeForm& form = light_lobe_form(kind);
        Lobe lobe;
        lobe.w = entry.required("w").number_in(form.weight);
        lobe.m = entry.child(key).number_in(form.value);
        light.lobes.push_back(lobe);
    }
}

// A light's "name": 1 to 64 bytes of printable UTF-8.
std::string read_light_name(const Node& node) {
    if (!node.value().is_string()) node.fail("must be a string");
    const std::string& name = node.value().get_ref<const std::string&>();
    if (name.empty() || name.size() > 64) node.fail("must be 1 to 64 bytes long");
    const bool control = std::any_of(name.begin(), name.end(), [](char c) {
        return static_cast<unsigned char>(c) < 0x20 || c == 0x7F;
    });
    if (control || !text::is_valid_utf8(name)) node.fail("must be UTF-8 text without control characters");
    return name;
}

void read_attenuation(const Node& node, Light& light) {
    const json& value = node.value();
    if (value.is_string()) {
        const std::size_t which = node.one_of({"constant", "inverse", "physical"});
        light.att_constant = which == 0 ? 1.0 : 0.0;
        light.att_linear = which == 1 ? 1.0 : 0.0;
        light.att_quadratic = which == 2 ? 1.0 : 0.0;
        return;
    }
    if (!value.is_array() || value.size() != 3 ||
        !std::all_of(value.begin(), value.end(), [](const json& e) { return e.is_number(); }))
        node.fail("must be an array of 3 numbers [S_c, S_l, S_q] or \"constant\", \"inverse\" or \"physical\"");
    const dvec3 s = node.vec3_in(closed(0.0, 1e6));
    if (s.x == 0.0 && s.y == 0.0 && s.z == 0.0) node.fail("must not be all zero");
    light.att_constant = s.x;
    light.att_linear = s.y;
    light.att_quadratic = s.z;
}

// The light's colour: "color" (RGB), "temperature_k" (a black body) or
// "illuminant" (a CIE standard illuminant), at most one of them
// (docs/spec.md#71-spectral-lights). A spectral light's RGB is computed here,
// once, so the GPU and the reference both use it.
void read_light_color(const Node& node, Light& light) {
    const char* given[] = {"color", "temperature_k", "illuminant"};
    std::vector<std::string> present;
    for (const char* key : given)
        if (node.has(key)) present.push_back(key);
    if (present.size() > 1) {
        const std::string who = light.name.empty() ? "this light" : "light " + text::quote(light.name);
        node.child(present[1]).fail(who + " gives both \"" + present[0] + "\" and \"" + present[1] +
                                    "\"; give one colour");
    }
    if (node.has("color")) {
        light.color = node.child("color").vec3_in(kUnit);
        return;
    }
    if (!node.has("temperature_k") && !node.has("illuminant")) return;
    const Node source = node.child(present[0]);
    try {
        if (node.has("temperature_k")) {
            light.temperature_k = source.number_in(closed(spectral::kMinKelvin, spectral::kMaxKelvin));
            light.color = spectral::temperature_rgb(light.temperature_k);
        } else {
            light.illuminant = spectral::illuminant_names()[source.one_of(spectral::illuminant_names())];
            light.color = spectral::illuminant_rgb(light.illuminant);
        }
    } catch (const spectral::SpectralError& error) {
        source.fail(std::string("cannot make its colour: ") + error.what());
    }
}

// A rect's "size": [w, h], each in kEmitterLength.
void read_rect_size(const Node& node, Light& light) {
    const json& value = node.value();
    if (!value.is_array() || value.size() != 2 ||
        !std::all_of(value.begin(), value.end(), [](const json& e) { return e.is_number(); }))
        node.fail("must be an array of 2 numbers [w, h]");
    light.size[0] = node.at(0).number_in(kEmitterLength);
    light.size[1] = node.at(1).number_in(kEmitterLength);
}

// A rect's "up", or its default; it must leave the rect a frame (as the camera's up).
void read_rect_up(const Node& node, Light& light) {
    if (!node.has("up")) {
        light.up = default_rect_up(light.normal);
        return;
    }
    const Node up = node.child("up");
    light.up = up.direction();
    if (glm::length(glm::cross(light.normal, light.up)) < 1e-6)  // both unit: |n x up| = sin(angle)
        up.fail("must not be parallel to the light's normal");
}

// The keys of the light's own type (light_keys).
void read_type_keys(const Node& node, Light& light) {
    switch (light.type) {
        case LightType::directional:
            light.direction = node.required("direction").direction();
            break;
        case LightType::point:
        case LightType::spot:
            light.position = node.required("position").vec3_in(kCoordinate);
            if (node.has("attenuation")) read_attenuation(node.child("attenuation"), light);
            if (light.type == LightType::spot) {
                light.spot_direction = node.required("spot_direction").direction();
                if (node.has("spot_exponent"))
                    light.spot_exponent = node.child("spot_exponent").number_in(kSpotExponent);
            }
            break;
        case LightType::rect:
        case LightType::disk:
            light.position = node.required("position").vec3_in(kCoordinate);
            light.normal = node.required("normal").direction();
            if (light.type == LightType::rect) {
                read_rect_size(node.required("size"), light);
                read_rect_up(node, light);
            } else {
                light.radius = node.required("radius").number_in(kEmitterLength);
            }
            break;
        case LightType::sky:
            if (node.has("up")) light.up = node.child("up").direction();
            break;
    }
}

}  // namespace

Light read_light(const Node& node) {
    node.expect_object();
    Light light;
    light.type = static_cast<LightType>(node.required("type").one_of(kLightTypes));
    std::vector<std::string> allowed = {"name",    "type",  "intensity", "color",  "temperature_k",
                                        "illuminant", "enabled", "lobes", "shadow"};
    const std::vector<std::string> own = light_keys(light.type);
    allowed.insert(allowed.end(), own.begin(), own.end());
    node.check_keys(allowed, [](const std::string& key) { return light_key_owners(key); });

    read_type_keys(node, light);
    if (node.has("intensity")) light.intensity = node.child("intensity").number_in(closed(0.0, 10.0));
    if (node.has("name")) light.name = read_light_name(node.child("name"));
    read_light_color(node, light);
    if (node.has("enabled")) light.enabled = node.child("enabled").boolean();
    if (node.has("shadow")) light.shadow = node.child("shadow").boolean();
    if (node.has("ambient")) light.ambient = node.child("ambient").vec3_in(kUnit);  // classic models
    if (node.has("lobes")) read_light_lobes(node.child("lobes"), light);
    return light;
}

json light_json(const Light& light) {
    const auto vec = [](const dvec3& v) { return json::array({v.x, v.y, v.z}); };
    json out = {{"type", to_string(light.type)}, {"intensity", light.intensity}, {"enabled", light.enabled}};
    // A spectral light is written as its spectrum, which the loader turns back into the same colour.
    if (light.temperature_k > 0.0)
        out["temperature_k"] = light.temperature_k;
    else if (!light.illuminant.empty())
        out["illuminant"] = light.illuminant;
    else
        out["color"] = vec(light.color);
    switch (light.type) {
        case LightType::directional: out["direction"] = vec(light.direction); break;
        case LightType::point:
        case LightType::spot:
            out["position"] = vec(light.position);
            out["attenuation"] = json::array({light.att_constant, light.att_linear, light.att_quadratic});
            if (light.type == LightType::spot) {
                out["spot_direction"] = vec(light.spot_direction);
                out["spot_exponent"] = light.spot_exponent;
            }
            break;
        case LightType::rect:
            out["position"] = vec(light.position);
            out["normal"] = vec(light.normal);
            out["up"] = vec(light.up);
            out["size"] = json::array({light.size[0], light.size[1]});
            break;
        case LightType::disk:
            out["position"] = vec(light.position);
            out["normal"] = vec(light.normal);
            out["radius"] = light.radius;
            break;
        case LightType::sky: out["up"] = vec(light.up); break;
    }
    if (light.ambient != dvec3(0.0)) out["ambient"] = vec(light.ambient);  // absent = none
    if (light.shadow) out["shadow"] = true;                                // absent = false
    if (!light.name.empty()) out["name"] = light.name;
    if (!light.lobes.empty()) {
        json lobes = json::array();
        for (const Lobe& lobe : light.lobes)
            lobes.push_back({{"w", lobe.w}, {light.lobe_kind == LobeKind::beckmann ? "m" : "n", lobe.m}});
        out["lobes"] = std::move(lobes);
    }
    return out;
}

}  // namespace m3055::scene_json
