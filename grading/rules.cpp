#include "grading/rules.h"

#include "analysis/lighting_ratio.h"
#include "io/message_text.h"
#include "models/model_spec.h"
#include "scene/presets.h"

#include <cmath>

namespace m3055::grading {

namespace {

using text::format_number;

std::string fixed(double value, int digits = 3) {
    char out[64];
    std::snprintf(out, sizeof out, "%.*f", digits, value);
    return out;
}

std::string object_name(int index) { return "objects[" + std::to_string(index) + "]"; }

// Passes when `ok`; the reason is said either way.
Check result(const Rule& rule, bool ok, std::string reason) {
    return {rule.label, rule.points, ok ? rule.points : 0.0, ok, std::move(reason)};
}

Check check_model(const Rule& rule, const Scene& scene) {
    if (rule.object >= int(scene.objects.size()))
        return result(rule, false, "no " + object_name(rule.object) + " (the scene has " +
                                       std::to_string(scene.objects.size()) + (scene.objects.size() == 1 ? " object)" : " objects)"));
    for (int i = 0; i < int(scene.objects.size()); ++i) {
        if (rule.object >= 0 && i != rule.object) continue;
        const Material& material = scene.objects[std::size_t(i)].material;
        if (material.model_name() != rule.text)
            return result(rule, false, object_name(i) + " is " + material.shown_name() + ", not " + rule.text);
    }
    if (scene.objects.empty()) return result(rule, false, "the scene has no objects");
    return result(rule, true, (rule.object >= 0 ? object_name(rule.object) : "every object") + " is " + rule.text);
}

bool lights_up(const Light& light) { return light.enabled && light.intensity > 0; }

// "3 lights enabled", "1 rect light enabled, not 2": the enabled lights, of the rule's type if it names one.
Check check_light_count(const Rule& rule, const Scene& scene) {
    int count = 0;
    for (const Light& light : scene.lights)
        count += lights_up(light) && (!rule.of_type || light.type == rule.light_type) ? 1 : 0;
    const int want = int(rule.min);
    const std::string kind = rule.of_type ? std::string(to_string(rule.light_type)) + " " : "";
    return result(rule, count == want,
                  std::to_string(count) + " " + kind + (count == 1 ? "light enabled" : "lights enabled") +
                      (count == want ? "" : ", not " + std::to_string(want)));
}

const Light* named_light(const Scene& scene, const std::string& name) {
    for (const Light& light : scene.lights)
        if (light.name == name) return &light;
    return nullptr;
}

// "no light named "key"", and, when a light's name differs from it only by
// case, that names are case-sensitive.
std::string no_light_named(const Scene& scene, const std::string& name) {
    const std::string out = "no light named " + text::quote(name);
    for (const Light& light : scene.lights)
        if (same_but_case(light.name, name))
            return out + " (names are case-sensitive: the scene has " + text::quote(light.name) + ")";
    return out;
}

// Warmth of a light's colour: how much redder than blue it is (c_r - c_b),
// the axis along which a warm (orange) and a cool (blue) key differ. A kelvin
// or illuminant light's colour is its spectrum's RGB at luminance 1.
double warmth(const Light& light) { return light.color.r - light.color.b; }

std::string kelvin_text(double kelvin) { return format_number(kelvin) + " K"; }

Check check_warmer(const Rule& rule, const Scene& scene) {
    const Light* warm = named_light(scene, rule.text);
    const Light* other = named_light(scene, rule.other);
    if (!warm || !other)
        return result(rule, false, no_light_named(scene, !warm ? rule.text : rule.other));
    // Two black bodies: the lower temperature is the warmer light (the studio's sense).
    const bool kelvin = warm->temperature_k > 0.0 && other->temperature_k > 0.0;
    const bool ok = kelvin ? warm->temperature_k < other->temperature_k : warmth(*warm) > warmth(*other);
    const std::string values =
        kelvin ? " (" + kelvin_text(warm->temperature_k) + " against " + kelvin_text(other->temperature_k) + ")"
               : " (red - blue " + fixed(warmth(*warm)) + " against " + fixed(warmth(*other)) + ")";
    return result(rule, ok, text::quote(rule.text) + (ok ? " is warmer than " : " is not warmer than ") +
                                text::quote(rule.other) + values);
}

Check check_temperature(const Rule& rule, const Scene& scene) {
    const Light* light = named_light(scene, rule.text);
    if (!light) return result(rule, false, no_light_named(scene, rule.text));
    const std::string range = "[" + kelvin_text(rule.min) + ", " + kelvin_text(rule.max) + "]";
    if (!(light->temperature_k > 0.0))
        return result(rule, false, text::quote(rule.text) + " has no \"temperature_k\" (" +
                                       (light->illuminant.empty() ? "an RGB colour" : "illuminant " + light->illuminant) +
                                       "), wanted " + range);
    const bool ok = light->temperature_k >= rule.min && light->temperature_k <= rule.max;
    return result(rule, ok, text::quote(rule.text) + " is " + kelvin_text(light->temperature_k) +
                                (ok ? ", within " : ", not within ") + range);
}

// The light casts shadows: its "shadow" is true, and it is on (a light that is off casts nothing).
Check check_shadow(const Rule& rule, const Scene& scene) {
    const Light* light = named_light(scene, rule.text);
    if (!light) return result(rule, false, no_light_named(scene, rule.text));
    const std::string name = text::quote(rule.text);
    if (!light->shadow) return result(rule, false, name + " casts no shadows (its \"shadow\" is false)");
    if (!lights_up(*light)) return result(rule, false, name + " is off (disabled or of intensity 0): it casts no shadows");
    return result(rule, true, name + " casts shadows");
}

Check check_key_to_fill(const Rule& rule, const Scene& scene) {
    const KeyFillRatio ratio = key_to_fill_ratio(scene);
    if (!ratio.ok()) return result(rule, false, ratio.problem);
    const std::string range = format_number(rule.min) + ":1 to " + format_number(rule.max) + ":1";
    const bool ok = ratio.ratio >= rule.min && ratio.ratio <= rule.max;
    return result(rule, ok, "key-to-fill " + ratio.text() + (ok ? ", within " : ", not within ") + range);
}

Check check_eq14(const Rule& rule, const Scene& scene) {
    if (rule.object >= int(scene.objects.size())) return result(rule, false, "no " + object_name(rule.object));
    const Material& material = scene.objects[std::size_t(rule.object)].material;
    if (material.model().family != Family::metal)
        return result(rule, false, object_name(rule.object) + " is " + material.shown_name() + ", not a metal model");
    const double peak = highlight_peak(material);
    const double off = 100.0 * std::abs(peak - 1.0);
    const bool ok = off <= rule.max;
    return result(rule, ok, object_name(rule.object) + ": highlight centre d + sum = " + fixed(peak, 4) + ", " +
                                fixed(off, 2) + " % from 1 (eq. 14), allowed " + format_number(rule.max) + " %");
}

Check check_range(const Rule& rule, const nlohmann::json& document) {
    const std::string name = text::cut_end(rule.text, text::kMaxPathBytes);
    const std::string range = "[" + format_number(rule.min) + ", " + format_number(rule.max) + "]";
    const nlohmann::json* value = find_scene_value(document, rule.text);
    if (!value) return result(rule, false, name + ": not in the scene");
    if (!value->is_number()) return result(rule, false, name + ": not a number");
    const double v = value->get<double>();
    const bool ok = v >= rule.min && v <= rule.max;
    return result(rule, ok, name + " = " + format_number(v) + (ok ? ", within " : ", not within ") + range);
}

// A value as a reason shows it: a string quoted, true/false, a number as typed.
std::string value_text(const nlohmann::json& value) {
    if (value.is_string()) return text::quote(value.get<std::string>());
    if (value.is_number()) return format_number(value.get<double>());
    if (value.is_boolean() || value.is_null()) return value.dump();
    return value.is_array() ? "a list" : "an object";
}

Check check_equals(const Rule& rule, const nlohmann::json& document) {
    const std::string name = text::cut_end(rule.text, text::kMaxPathBytes);
    const nlohmann::json* value = find_scene_value(document, rule.text);
    const std::string wanted = value_text(rule.value);
    if (!value) return result(rule, false, name + ": not in the scene, wanted " + wanted);
    if (*value == rule.value) return result(rule, true, name + " is " + wanted);
    std::string reason = name + " is " + value_text(*value) + ", not " + wanted;
    if (value->is_string() && rule.value.is_string() &&
        same_but_case(value->get<std::string>(), rule.value.get<std::string>()))
        reason += " (values are case-sensitive)";
    return result(rule, false, reason);
}

}  // namespace

bool same_but_case(const std::string& a, const std::string& b) {
    if (a.size() != b.size() || a == b) return false;
    const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
    for (std::size_t i = 0; i < a.size(); ++i)
        if (lower(a[i]) != lower(b[i])) return false;
    return true;
}

Check check_rule(const Rule& rule, const Scene& scene, const nlohmann::json& document) {
    switch (rule.kind) {
        case RuleKind::model: return check_model(rule, scene);
        case RuleKind::light_count: return check_light_count(rule, scene);
        case RuleKind::warmer: return check_warmer(rule, scene);
        case RuleKind::key_to_fill: return check_key_to_fill(rule, scene);
        case RuleKind::eq14: return check_eq14(rule, scene);
        case RuleKind::range: return check_range(rule, document);
        case RuleKind::temperature: return check_temperature(rule, scene);
        case RuleKind::equals: return check_equals(rule, document);
        case RuleKind::shadow: return check_shadow(rule, scene);
    }
    return result(rule, false, "unknown rule");
}

namespace {

// "objects[0].material.m" -> the JSON pointer "/objects/0/material/m".
nlohmann::json::json_pointer pointer_of(const std::string& path) {
    std::string pointer = "/";
    for (char c : path) {
        if (c == '.' || c == '[') {
            if (pointer.back() != '/') pointer += '/';
        } else if (c != ']') {
            pointer += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
        }
    }
    return nlohmann::json::json_pointer(pointer);
}

}  // namespace

const nlohmann::json* find_scene_value(const nlohmann::json& document, const std::string& path) {
    try {
        const auto pointer = pointer_of(path);
        if (document.contains(pointer)) return &document.at(pointer);
    } catch (const nlohmann::json::exception&) {
    }
    return nullptr;
}

}  // namespace m3055::grading
