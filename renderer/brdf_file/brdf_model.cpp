#include "brdf_file/brdf_model.h"

#include "brdf_file/brdf_glsl.h"
#include "io/input_file.h"
#include "io/message_text.h"
#include "models/model_table.h"

#include <algorithm>
#include <deque>
#include <filesystem>
#include <memory>

namespace m3055 {

namespace {

struct Loaded {
    BrdfModel model;
    std::string key;  // canonical path + "\n" + text: the same file unchanged
};

std::deque<Loaded>& loaded() {
    static std::deque<Loaded> models;
    return models;
}

ParamSpec table_param(const BrdfParam& p, const std::string& field, const std::string& file) {
    ParamSpec out;
    out.name = field;
    out.label = p.name;
    out.help = p.name + " (" + file + ":" + std::to_string(p.line) + ")";
    out.cite = file;
    out.fallback = p.fallback;
    switch (p.kind) {
        case BrdfParam::Kind::number:
            out.kind = ParamKind::number;
            out.range = closed(p.min, p.max);
            break;
        case BrdfParam::Kind::colour: out.kind = ParamKind::colour; break;
        case BrdfParam::Kind::flag: out.kind = ParamKind::flag; break;
    }
    return out;
}

ModelSpec spec_of(const BrdfFile& file, int id) {
    ModelSpec spec;
    spec.name = "brdf_" + std::to_string(id);
    spec.label = std::filesystem::path(file.name).stem().string() + " (.brdf)";
    spec.citation = file.name;
    spec.summary = "BRDF Explorer file " + file.name;
    spec.family = Family::brdf;
    std::vector<std::string> fields;
    for (std::size_t i = 0; i < file.params.size(); ++i) {
        fields.push_back("b" + std::to_string(id) + "_" + std::to_string(i));
        spec.params.push_back(table_param(file.params[i], fields.back(), file.name));
    }
    ParamSpec axis;
    axis.name = "axis", axis.label = "tangent axis", axis.kind = ParamKind::direction, axis.fallback = {0.0, 1.0, 0.0};
    axis.help = "X = normalize(axis x N), Y = N x X", axis.cite = "docs/models.md";
    spec.params.push_back(axis);
    spec.glsl_file = "generated/brdf_" + std::to_string(id) + ".glsl";
    spec.glsl_hook = "m3055_b" + std::to_string(id) + "_hook";
    spec.glsl_sources = brdf_glsl_sources(file, id, spec.glsl_file, spec.glsl_hook, fields);
    spec.glsl_sources_es = brdf_glsl_es_sources(file, id, spec.glsl_file, spec.glsl_hook, fields);
    return spec;
}

}  // namespace

std::string BrdfModel::field(std::string_view name) const {
    for (std::size_t i = 0; i < file.params.size(); ++i)
        if (file.params[i].name == name) return spec->params[i].name;
    return std::string();
}

const BrdfModel& load_brdf_model(const io::InputPath& file_name) {
    const std::string& path = file_name.path;
    std::string text;
    try {
        text = io::read_input_file(file_name, std::size_t(1) << 20);
    } catch (const io::InputError& e) {
        throw BrdfError(e.what());
    }
    std::error_code ec;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
    const std::string key = (ec ? path : canonical.string()) + "\n" + text;
    for (const Loaded& l : loaded())
        if (l.key == key) return l.model;
    BrdfFile file = parse_brdf(text, text::quote_name(file_name.shown));
    ModelTable& table = mutable_model_table();
    const int id = static_cast<int>(table.models().size());  // the id add() gives it
    const ModelSpec* spec = nullptr;
    try {
        spec = &table.add(spec_of(file, id));
    } catch (const std::invalid_argument& e) {
        throw BrdfError(file.name + ": " + e.what());
    }
    loaded().push_back({BrdfModel{spec, std::move(file), path}, key});
    return loaded().back().model;
}

const BrdfModel& load_brdf_model(const std::string& path) { return load_brdf_model(io::InputPath::as_given(path)); }

const BrdfModel* find_brdf_model(const ModelSpec& spec) {
    for (const Loaded& l : loaded())
        if (l.model.spec == &spec) return &l.model;
    return nullptr;
}

void retire_brdf_model(const ModelSpec& spec) {
    if (find_brdf_model(spec)) mutable_model_table().retire(spec);
}

Material reload_brdf_material(const Material& current, const std::string& path) {
    const BrdfModel& fresh = load_brdf_model(path);
    Material out(*fresh.spec);
    const BrdfModel* old = find_brdf_model(current.model());
    if (!old) return out;
    for (const BrdfParam& p : fresh.file.params) {
        const BrdfParam* before = old->file.find(p.name);
        if (!before || before->kind != p.kind) continue;
        const std::string from = old->field(p.name), to = fresh.field(p.name);
        switch (p.kind) {
            case BrdfParam::Kind::number:
                out.set_number(to, std::clamp(current.number(from), p.min, p.max));
                break;
            case BrdfParam::Kind::colour: out.set_vec3(to, current.vec3(from)); break;
            case BrdfParam::Kind::flag: out.set_flag(to, current.flag(from)); break;
        }
    }
    out.set_vec3("axis", current.vec3("axis"));
    return out;
}

}  // namespace m3055
