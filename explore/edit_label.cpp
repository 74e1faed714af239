#include "explore/edit_label.h"

#include "models/model_spec.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace m3055::explore {

std::string label_number(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    if (value == 0.0) return "0";  // no "-0"
    char buffer[64];
    const double magnitude = std::fabs(value);
    if (magnitude < 1e-3 || magnitude >= 1e6) {
        std::snprintf(buffer, sizeof buffer, "%.2e", value);
        return buffer;
    }
    // Three significant digits, then no trailing zeros after the point
    // (printf's %g would switch to scientific for 1560).
    const int digits_before_point = static_cast<int>(std::floor(std::log10(magnitude))) + 1;
    const int decimals = std::max(0, 3 - digits_before_point);
    const double step = std::pow(10.0, digits_before_point - 3);
    const double rounded = std::round(value / step) * step;
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, rounded);
    std::string text = buffer;
    if (text.find('.') != std::string::npos) {
        while (text.back() == '0') text.pop_back();
        if (text.back() == '.') text.pop_back();
    }
    return text;
}

namespace {

// Collects the first difference: each compare_* call does nothing once one is found.
class FirstChange {
public:
    explicit FirstChange(std::string prefix) : prefix_(std::move(prefix)) {}

    void number(const std::string& name, double a, double b) {
        if (found() || a == b || (std::isnan(a) && std::isnan(b))) return;
        change_ = {path(name), label_number(a), label_number(b)};
    }
    void whole(const std::string& name, bool differs) {  // a colour, a position, a list: no values shown
        if (!found() && differs) change_ = {path(name), "", ""};
    }
    void text(const std::string& name, const std::string& a, const std::string& b) {
        if (found() || a == b) return;
        change_ = {path(name), a, b};
        if (a.empty() || b.empty()) change_.from.clear(), change_.to.clear();  // a value added or removed
    }
    void flag(const std::string& name, bool a, bool b) {
        if (!found() && a != b) change_ = {path(name), a ? "on" : "off", b ? "on" : "off"};
    }
    void vector(const std::string& name, const dvec3& a, const dvec3& b) { whole(name, a != b); }
    void lobes(const std::string& name, const LobeList& a, const LobeList& b, const char* value_key) {
        if (found()) return;
        if (a.size() != b.size()) return whole(name, true);
        for (std::size_t j = 0; j < a.size(); ++j) {
            const std::string lobe = name + "[" + std::to_string(j) + "]";
            number(lobe + ".w", a[j].w, b[j].w);
            number(lobe + "." + value_key, a[j].m, b[j].m);
        }
    }

    bool found() const { return !change_.empty(); }
    FieldChange take() { return std::move(change_); }

private:
    std::string path(const std::string& name) const { return prefix_.empty() ? name : prefix_ + name; }
    std::string prefix_;
    FieldChange change_;
};

bool same_values(const Material& a, const Material& b, const ParamSpec& param) {
    for (int i = param.offset; i < param.offset + param.size; ++i)
        if (a.values()[std::size_t(i)] != b.values()[std::size_t(i)]) return false;
    return true;
}

const char* lobe_value_key(LobeKind kind) { return kind == LobeKind::beckmann ? "m" : "n"; }

}  // namespace

FieldChange material_change(const Material& before, const Material& after) {
    if (&before.model() != &after.model()) return {"model", before.shown_name(), after.shown_name()};
    const ModelSpec& model = after.model();
    const bool from_file = model.family == Family::brdf;
    FirstChange first("");
    for (const ParamSpec& param : model.params) {
        if (!param.spectrum_key.empty()) {
            const ReflectanceSpectrum *a = before.colour_spectrum(), *b = after.colour_spectrum();
            const bool differs = (a == nullptr) != (b == nullptr) || (a && b && !(*a == *b));
            first.whole(param.spectrum_key, differs);
        }
        if (same_values(before, after, param)) continue;
        // A .brdf file's parameters are written under "params" by the file's names.
        const std::string name = from_file && param.name != "axis" ? "params." + param.label : param.name;
        switch (param.kind) {
            case ParamKind::number: first.number(name, before.number(param.name), after.number(param.name)); break;
            case ParamKind::colour:
            case ParamKind::direction: first.vector(name, before.vec3(param.name), after.vec3(param.name)); break;
            case ParamKind::choice:
                first.text(name, before.choice_name(param.name), after.choice_name(param.name));
                break;
            case ParamKind::flag: first.flag(name, before.flag(param.name), after.flag(param.name)); break;
            case ParamKind::lobes:
                first.lobes(name, before.lobes(param.name), after.lobes(param.name),
                            param.form_for(after).key.c_str());
                break;
        }
        if (first.found()) break;
    }
    return first.take();
}

FieldChange light_change(const Light& before, const Light& after, int index) {
    FirstChange first("");
    first.text("name", before.name, after.name);
    first.flag("enabled", before.enabled, after.enabled);
    first.text("type", to_string(before.type), to_string(after.type));
    first.vector("direction", before.direction, after.direction);
    first.vector("position", before.position, after.position);
    first.number("intensity", before.intensity, after.intensity);
    first.number("temperature_k", before.temperature_k, after.temperature_k);
    first.text("illuminant", before.illuminant, after.illuminant);
    first.vector("color", before.color, after.color);
    first.whole("attenuation", before.att_constant != after.att_constant || before.att_linear != after.att_linear ||
                                   before.att_quadratic != after.att_quadratic);
    first.vector("spot_direction", before.spot_direction, after.spot_direction);
    first.number("spot_exponent", before.spot_exponent, after.spot_exponent);
    first.vector("ambient", before.ambient, after.ambient);
    first.flag("shadow", before.shadow, after.shadow);
    first.vector("normal", before.normal, after.normal);
    first.vector("up", before.up, after.up);
    first.number("size[0]", before.size[0], after.size[0]);
    first.number("size[1]", before.size[1], after.size[1]);
    first.number("radius", before.radius, after.radius);
    first.whole("lobes", before.lobe_kind != after.lobe_kind || before.lobes.size() != after.lobes.size());
    first.lobes("lobes", LobeList(before.lobes), LobeList(after.lobes), lobe_value_key(after.lobe_kind));
    FieldChange change = first.take();
    if (change.empty()) return change;
    if (change.what == "name") {  // "rename light key -> fill" (a name added or removed: "rename light 2")
        change.what = "rename light";
        if (before.name.empty() || after.name.empty()) change.what += " " + std::to_string(index);
        return change;
    }
    change.what = "light " + (after.name.empty() ? std::to_string(index) : after.name) + " " + change.what;
    return change;
}

FieldChange object_change(const Object& before, const Object& after, int index) {
    const std::string prefix = "objects[" + std::to_string(index) + "]";
    FirstChange first(prefix + ".");
    first.text("shape", to_string(before.shape), to_string(after.shape));
    first.vector("center", before.center, after.center);
    first.number("radius", before.radius, after.radius);
    first.vector(after.shape == Shape::plane ? "normal" : "axis", before.axis, after.axis);
    first.number("size", before.size, after.size);
    first.vector("rotation_deg", before.rotation_deg, after.rotation_deg);
    first.number("height", before.height, after.height);
    first.flag("capped", before.capped, after.capped);
    first.number("major_radius", before.major_radius, after.major_radius);
    first.number("minor_radius", before.minor_radius, after.minor_radius);
    first.number("segments", before.segments, after.segments);
    if (first.found()) return first.take();
    FieldChange change = material_change(before.material, after.material);
    if (!change.empty() && change.what != "model") change.what = prefix + ".material." + change.what;
    return change;
}

FieldChange camera_change(const Camera& before, const Camera& after) {
    FirstChange first("camera.");
    first.text("projection", to_string(before.projection), to_string(after.projection));
    first.vector("position", before.position, after.position);
    first.vector("target", before.target, after.target);
    first.vector("up", before.up, after.up);
    first.number("fov_y_deg", before.fov_y_deg, after.fov_y_deg);
    first.number("height", before.height, after.height);
    return first.take();
}

FieldChange display_change(const Display& before, const Display& after) {
    FirstChange first("display.");
    first.number("width", before.width, after.width);
    first.number("height", before.height, after.height);
    first.number("bits", before.bits, after.bits);
    first.flag("dither", before.dither, after.dither);
    first.text("view_transform", to_string(before.view_transform), to_string(after.view_transform));
    return first.take();
}

}  // namespace m3055::explore
