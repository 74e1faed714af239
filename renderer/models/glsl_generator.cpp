#include "models/glsl_generator.h"

#include "models/model_table.h"
#include "spectral/conductor.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <mutex>
#include <set>

namespace m3055 {

namespace {

constexpr Family kFamilies[] = {Family::opaque, Family::translucent, Family::metal, Family::classic, Family::brdf};

std::string upper(std::string text) {
    for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

// Each family's dispatchers: from the material's model id to its hooks. The
// hooks have exactly these signatures (reference/reference.h has the C++ twins).
struct Dispatcher {
    Family family;
    bool specular;  // the classic family's second hook (ModelSpec::glsl_specular)
    const char* name;
    const char* result;
    const char* params;
    const char* args;
    const char* otherwise;  // no model of the family matched
};

const Dispatcher kDispatchers[] = {
    {Family::opaque, false, "opaque_shade", "vec3", "Material mat, vec3 P, vec3 N, vec3 V", "mat, P, N, V",
     "return vec3(0.0);"},
    {Family::translucent, false, "translucent_shade", "void",
     "Material mat, vec3 P, vec3 N, vec3 V, out vec3 color, out vec3 transmittance",
     "mat, P, N, V, color, transmittance", "color = vec3(0.0);\n    transmittance = vec3(1.0);"},
    {Family::metal, false, "metal_lobe_sum", "float", "Material mat, int i, vec3 N, vec3 V, vec3 L, float NoL, float NoV",
     "mat, i, N, V, L, NoL, NoV", "return 0.0;"},
    {Family::classic, false, "classic_diffuse", "float", "Material mat, float NoL, float NoV, float LoV",
     "mat, NoL, NoV, LoV", "return 0.0;"},
    {Family::classic, true, "classic_specular", "vec3", "Material mat, vec3 N, vec3 L, vec3 V, float NoL, float NoV",
     "mat, N, L, V, NoL, NoV", "return vec3(0.0);"},
    {Family::brdf, false, "brdf_eval", "vec3", "Material mat, vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y",
     "mat, L, V, N, X, Y", "return vec3(0.0);"},
};

std::string glsl_type(ParamKind kind) {
    switch (kind) {
        case ParamKind::number: return "float";
        case ParamKind::colour:
        case ParamKind::direction: return "vec3";
        case ParamKind::choice:
        case ParamKind::flag: return "int";
        case ParamKind::lobes: return "vec2";
    }
    return "float";
}

// Float k of a record, from the texels t0, t1, ... fetch_material reads.
std::string record_float(int k) { return "t" + std::to_string(k / 4) + "." + "xyzw"[k % 4]; }

std::string record_floats(int first, int count) {
    if (count == 1) return record_float(first);
    std::string out = "vec" + std::to_string(count) + "(";
    for (int i = 0; i < count; ++i) out += (i ? ", " : "") + record_float(first + i);
    return out + ")";
}

std::string defines(const ModelTable& table) {
    std::string out;
    for (Family family : kFamilies)
        out += "#define FAMILY_" + upper(to_string(family)) + " " + std::to_string(static_cast<int>(family)) + "\n";
    for (const ModelSpec& spec : table.models())
        out += "#define MODEL_" + spec.macro_name() + " " + std::to_string(spec.id) + "\n";
    // Each constant once: same-named choices of two models either share a list
    // (distribution) or have different names (the metals' fresnel normal/full,
    // microfacet's none/schlick/dielectric); each model compares its own.
    std::set<std::string> seen;
    for (const ModelSpec& spec : table.models())
        for (const ParamSpec& param : spec.params)
            if (param.kind == ParamKind::choice)
                for (std::size_t i = 0; i < param.choices.size(); ++i) {
                    const std::string constant = upper(param.name + "_" + param.choices[i]);
                    if (seen.insert(constant).second)
                        out += "#define " + constant + " " + std::to_string(i) + "\n";
                }
    out += "#define CONDUCTOR_COS_SAMPLES " + std::to_string(spectral::kConductorCosSamples) + "\n";
    return out + "#define MAX_LOBES " + std::to_string(kMaxLobes) + "\n";
}

std::string material_struct(const ModelTable& table) {
    std::string out = "struct Material {\n    int model;   // MODEL_*\n    int family;  // FAMILY_*\n";
    std::set<std::string> fields;
    for (const ModelSpec& spec : table.models()) {
        for (const ParamSpec& param : spec.params) {
            if (!fields.insert(param.name).second) continue;
            if (param.kind == ParamKind::lobes)
                out += "    vec2 " + param.name + "[MAX_LOBES];  // (w_j, m_j or n_j)\n    int " + param.name +
                       "_count;\n";
            else
                out += "    " + glsl_type(param.kind) + " " + param.name + ";\n";
        }
        for (const DerivedValue& d : spec.derived)
            if (fields.insert(d.name).second)
                out += "    " + std::string(d.floats == 1 ? "float" : "vec" + std::to_string(d.floats)) + " " +
                       d.name + ";  // derived (" + spec.name + ")\n";
    }
    return out + "};\n";
}

// The branch of fetch_material that unpacks one model's record.
std::string unpack(const ModelSpec& spec) {
    std::string out = "#ifdef " + has_define(spec) + "\n    if (mat.model == MODEL_" + spec.macro_name() + ") {\n";
    for (int t = 1; t < (spec.gpu_floats + 3) / 4; ++t)
        out += "        vec4 t" + std::to_string(t) + " = m3055_material_texel(base + " + std::to_string(t) + ");\n";
    int k = 2;
    for (const ParamSpec& param : spec.params) {
        const std::string field = "        mat." + param.name;
        switch (param.kind) {
            case ParamKind::number: out += field + " = " + record_float(k) + ";\n"; break;
            case ParamKind::colour:
            case ParamKind::direction: out += field + " = " + record_floats(k, 3) + ";\n"; break;
            case ParamKind::choice:
            case ParamKind::flag: out += field + " = int(" + record_float(k) + ");\n"; break;
            case ParamKind::lobes:
                out += field + "_count = int(" + record_float(k) + ");\n";
                for (int j = 0; j < kMaxLobes; ++j)
                    out += field + "[" + std::to_string(j) + "] = " + record_floats(k + 1 + 2 * j, 2) + ";\n";
                break;
        }
        k += param.size;
    }
    for (const DerivedValue& d : spec.derived) {
        out += "        mat." + d.name + " = " + record_floats(k, d.floats) + ";\n";
        k += d.floats;
    }
    return out + "    }\n#endif\n";
}

std::string material_file(const ModelTable& table) {
    std::string out =
        "// Generated from the model table (renderer/models/builtin_models.cpp) by\n"
        "// renderer/models/glsl_generator.cpp: ids, struct Material, fetch_material.\n";
    out += defines(table);
    // A 2D texture, not a buffer texture: WebGL2 (GLSL ES 3.00) has no
    // samplerBuffer. Texel i of the records sits at (i % width, i / width).
    out += "\n#define M3055_MATERIAL_TEXTURE_WIDTH " + std::to_string(kMaterialTextureWidth) + "\n";
    out += "uniform sampler2D u_materials;  // the records of passes/material_buffer.cpp, RGBA32F\n";
    out += "uniform int u_material_texels;  // texels per record\n\n";
    out += "vec4 m3055_material_texel(int i) {\n"
           "    const int w = M3055_MATERIAL_TEXTURE_WIDTH;\n"
           "    return texelFetch(u_materials, ivec2(i % w, i / w), 0);\n}\n\n";
    out += material_struct(table);
    out += "\nMaterial fetch_material(int index) {\n    int base = index * u_material_texels;\n";
    out += "    vec4 t0 = m3055_material_texel(base);\n    Material mat;\n";
    out += "    mat.model = int(t0.x);\n    mat.family = int(t0.y);\n";
    for (const ModelSpec& spec : table.models()) out += unpack(spec);
    out += "    return mat;\n}\n\n// The families' dispatchers to their models' hooks (generated/models.glsl).\n";
    for (const Dispatcher& d : kDispatchers) out += std::string(d.result) + " " + d.name + "(" + d.params + ");\n";
    return out + "#ifdef HAS_AREA_LIGHTS\nvec3 lobe_exponents(Material mat, int i);\n#endif\n";
}

// A family's dispatcher: "if (mat.model == MODEL_X) return hook(...);" per model.
std::string dispatcher(const ModelTable& table, const Dispatcher& d) {
    const bool returns = std::string(d.result) != "void";
    std::string out = "\n" + std::string(d.result) + " " + d.name + "(" + d.params + ") {\n";
    for (const ModelSpec& spec : table.models()) {
        const std::string& hook = d.specular ? spec.glsl_specular : spec.glsl_hook;
        if (spec.family != d.family || hook.empty()) continue;
        out += "#ifdef " + has_define(spec) + "\n    if (mat.model == MODEL_" + spec.macro_name() + ") ";
        out += returns ? "return " + hook + "(" + d.args + ");\n"
                       : "{\n        " + hook + "(" + d.args + ");\n        return;\n    }\n";
        out += "#endif\n";
    }
    return out + "    " + d.otherwise + "\n}\n";
}

// Area lights' second way of drawing directions and their lobe's control
// variate (glsl/common/lights.glsl): the Phong exponents about V's mirror
// direction of the material's highlight, each model's ModelSpec::glsl_lobe and
// glsl_control_lobe; 0 for a model without one. Third: 1 where the highlight is
// exactly that lobe (ModelSpec::glsl_lobe_exact).
std::string lobe_dispatcher(const ModelTable& table) {
    std::string out = "\n#ifdef HAS_AREA_LIGHTS\n#include \"common/lobe_hints.glsl\"\n\n"
                      "vec3 lobe_exponents(Material mat, int i) {\n";
    for (const ModelSpec& spec : table.models()) {
        if (spec.glsl_lobe.empty()) continue;
        const std::string control = spec.glsl_control_lobe.empty() ? spec.glsl_lobe : spec.glsl_control_lobe;
        out += "#ifdef " + has_define(spec) + "\n    if (mat.model == MODEL_" + spec.macro_name() + ") return vec3(" +
               spec.glsl_lobe + ", " + control + (spec.glsl_lobe_exact ? ", 1.0" : ", 0.0") + ");\n#endif\n";
    }
    return out + "    return vec3(0.0);\n}\n#endif\n";
}

std::string models_file(const ModelTable& table) {
    std::string out =
        "// Generated from the model table (renderer/models/builtin_models.cpp) by\n"
        "// renderer/models/glsl_generator.cpp: the models' GLSL files, and each\n"
        "// family's dispatcher from a material's model to its hook.\n";
    std::map<std::string, std::vector<const ModelSpec*>> files;  // a file once, for all its models
    std::vector<std::string> order;
    for (const ModelSpec& spec : table.models()) {
        if (!files.count(spec.glsl_file)) order.push_back(spec.glsl_file);
        files[spec.glsl_file].push_back(&spec);
    }
    for (const std::string& file : order) {
        std::string condition;
        for (const ModelSpec* spec : files[file])
            condition += (condition.empty() ? "" : " || ") + std::string("defined(") + has_define(*spec) + ")";
        out += "#if " + condition + "\n#include \"" + file + "\"\n#endif\n";
    }
    for (const Dispatcher& d : kDispatchers) out += dispatcher(table, d);
    return out + lobe_dispatcher(table);
}

}  // namespace

std::string has_define(const ModelSpec& model) { return "HAS_" + model.macro_name(); }

std::string family_define(int family) { return "HAS_FAMILY_" + upper(to_string(static_cast<Family>(family))); }

std::vector<std::string> every_model_define(const ModelTable& table) {
    std::set<std::string> out;
    for (const ModelSpec& spec : table.models()) {
        if (table.retired(spec)) continue;
        out.insert(has_define(spec));
        out.insert(family_define(static_cast<int>(spec.family)));
    }
    return {out.begin(), out.end()};
}

std::vector<std::pair<std::string, std::string>> generate_glsl(const ModelTable& table, bool glsl_es) {
    std::vector<std::pair<std::string, std::string>> out = {{"generated/material.glsl", material_file(table)},
                                                             {"generated/models.glsl", models_file(table)}};
    for (const ModelSpec& spec : table.models()) {
        const auto& sources = glsl_es && !spec.glsl_sources_es.empty() ? spec.glsl_sources_es : spec.glsl_sources;
        out.insert(out.end(), sources.begin(), sources.end());
    }
    return out;
}

std::vector<std::pair<std::string, std::string>> generated_glsl(bool glsl_es) {
    static std::mutex mutex;
    static std::uint64_t revision[2] = {0, 0};
    static std::vector<std::pair<std::string, std::string>> cached[2];
    const std::lock_guard<std::mutex> lock(mutex);
    const int which = glsl_es ? 1 : 0;
    if (cached[which].empty() || revision[which] != model_table().revision()) {
        cached[which] = generate_glsl(model_table(), glsl_es);
        revision[which] = model_table().revision();
    }
    return cached[which];
}

}  // namespace m3055
