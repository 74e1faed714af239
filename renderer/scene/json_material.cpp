#include "scene/json_material.h"

#include "models/model_table.h"
#include "scene/json_brdf.h"
#include "scene/json_spectrum.h"
#include "scene/spectral_colour.h"
#include "spectral/spectrum.h"

#include <glm/common.hpp>

namespace m3055::scene_json {

namespace {

json vec(const dvec3& v) { return json::array({v.x, v.y, v.z}); }

// The problem for a key the model does not read: another model's parameter is
// "not a parameter of model X" (with the model's hint, if it has one for it).
std::string misplaced(const ModelSpec& spec, const std::string& key) {
    if (!model_table().is_builtin_param(key)) return std::string();  // a plain "unknown key"
    const std::string problem = "not a parameter of model " + spec.name;
    for (const auto& [hinted, hint] : spec.misplaced_hints)
        if (hinted == key) return problem + " (" + hint + ")";
    return problem;
}

// A parameter the file leaves out: its default, which may follow an earlier
// value (ka <- kd; the lobes of the distribution read before).
void read_absent(const Node& node, const ParamSpec& param, Material& material) {
    if (param.required) node.required(param.name);  // throws "is required"
    if (!param.default_from.empty()) material.set_vec3(param.name, material.vec3(param.default_from));
    if (param.kind == ParamKind::lobes) material.set_lobes(param.name, param.form_for(material).fallback);
}

// The parameter that stands in for `param` when the file gives it ("conductor"
// for "color": docs/spec.md#72-measured-metals), or nullptr. Its first choice
// ("none") names no replacement: `param` is then read as ever.
const ParamSpec* replacement_given(const Node& node, const ModelSpec& spec, const ParamSpec& param) {
    for (const ParamSpec& other : spec.params)
        if (other.replaces == param.name && node.has(other.name) && node.child(other.name).one_of(other.choices) != 0)
            return &other;
    return nullptr;
}

void read_param(const Node& node, const ModelSpec& spec, const ParamSpec& param, Material& material) {
    const bool spectrum = !param.spectrum_key.empty() && node.has(param.spectrum_key);
    if (const ParamSpec* replacement = replacement_given(node, spec, param)) {
        for (const std::string& given : {param.name, spectrum ? param.spectrum_key : std::string()})
            if (!given.empty() && node.has(given))
                node.child(replacement->name)
                    .fail("the material gives both \"" + given + "\" and \"" + replacement->name + "\"; give one");
        return;
    }
    if (spectrum) {
        // docs/spec.md#73-spectral-colours: the spectrum, and as the colour its D65 RGB.
        if (node.has(param.name))
            node.child(param.spectrum_key)
                .fail("the material gives both \"" + param.name + "\" and \"" + param.spectrum_key + "\"; give one");
        const Node given = node.child(param.spectrum_key);
        const ReflectanceSpectrum read = read_spectrum(given);
        material.set_colour_spectrum(&read);
        try {
            material.set_vec3(param.name, glm::clamp(spectrum_d65_rgb(read), dvec3(0.0), dvec3(1.0)));
        } catch (const spectral::SpectralError& error) {
            given.fail(std::string("cannot make its colour: ") + error.what());
        }
        return;
    }
    if (!node.has(param.name)) return read_absent(node, param, material);
    const Node value = node.child(param.name);
    switch (param.kind) {
        case ParamKind::number: material.set_number(param.name, value.number_in(param.range)); break;
        case ParamKind::colour: material.set_vec3(param.name, value.vec3_in(kUnit)); break;
        case ParamKind::direction: material.set_vec3(param.name, value.direction()); break;
        case ParamKind::choice: material.set_choice(param.name, int(value.one_of(param.choices))); break;
        case ParamKind::flag: material.set_flag(param.name, value.boolean()); break;
        case ParamKind::lobes: {
            const LobeForm& form = param.form_for(material);
            const std::string other = form.key == "m" ? "n" : "m";
            material.set_lobes(param.name,
                               read_lobe_list(value, form.key, other, form.weight, form.value, form.owner));
            break;
        }
    }
}

json lobes_json(const LobeList& lobes, const std::string& key) {
    json out = json::array();
    for (const Lobe& lobe : lobes) out.push_back({{"w", lobe.w}, {key, lobe.m}});
    return out;
}

}  // namespace

Material read_material(const Node& node, const SceneFiles& files) {
    node.expect_object();
    if (is_brdf_material(node)) return read_brdf_material(node, files);
    const ModelTable& table = model_table();
    // The models a scene names: every entry but the .brdf files' (named "brdf" + "file").
    std::vector<std::string> names;
    for (const ModelSpec& model : table.models())
        if (model.family != Family::brdf) names.push_back(model.name);
    names.push_back("brdf");
    const ModelSpec& spec = table.get(names.at(node.required("model").one_of(names)));
    std::vector<std::string> allowed = spec.param_names();
    allowed.push_back("model");
    for (const ParamSpec& param : spec.params)
        if (!param.spectrum_key.empty()) allowed.push_back(param.spectrum_key);
    node.check_keys(allowed, [&](const std::string& key) { return misplaced(spec, key); });
    Material material(spec);
    for (const ParamSpec& param : spec.params) read_param(node, spec, param, material);
    return material;
}

json material_json(const Material& material, const PathWriting& writing) {
    const ModelSpec& spec = material.model();
    if (spec.family == Family::brdf) return brdf_material_json(material, writing);
    json out = {{"model", spec.name}};
    // Left out: a parameter at its default that scenes need not give, and one
    // that a given replacement stands in for ("color" of a conductor).
    auto written = [&](const ParamSpec& param) {
        if (param.kind == ParamKind::choice && !param.written_at_default &&
            material.choice(param.name) == int(param.fallback[0]))
            return false;
        for (const ParamSpec& other : spec.params)
            if (other.replaces == param.name && material.choice(other.name) != 0) return false;
        return true;
    };
    for (const ParamSpec& param : spec.params) {
        if (!written(param)) continue;
        if (!param.spectrum_key.empty() && material.colour_spectrum()) {
            out[param.spectrum_key] = spectrum_json(*material.colour_spectrum());
            continue;
        }
        switch (param.kind) {
            case ParamKind::number: out[param.name] = material.number(param.name); break;
            case ParamKind::colour:
            case ParamKind::direction: out[param.name] = vec(material.vec3(param.name)); break;
            case ParamKind::choice: out[param.name] = material.choice_name(param.name); break;
            case ParamKind::flag: out[param.name] = material.flag(param.name); break;
            case ParamKind::lobes:
                out[param.name] = lobes_json(material.lobes(param.name), param.form_for(material).key);
                break;
        }
    }
    return out;
}

}  // namespace m3055::scene_json
