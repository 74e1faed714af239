#include "scene/json_brdf.h"

#include "brdf_file/brdf_model.h"
#include "models/model_table.h"
#include "scene/load.h"

namespace m3055::scene_json {

namespace {

constexpr const char* kWhat = "a .brdf file";  // the kind of file, in a confinement's refusal

// A value read by `read`; a problem gets the .brdf's name appended.
template <class Read>
auto with_file(const std::string& file, Read read) {
    try {
        return read();
    } catch (const SceneError& e) {
        throw SceneError(std::string(e.what()) + " (" + file + ")");
    }
}

void read_value(const Node& node, const BrdfModel& model, const BrdfParam& p, Material& material) {
    const std::string field = model.field(p.name);
    with_file(model.file.name, [&] {
        switch (p.kind) {
            case BrdfParam::Kind::number: material.set_number(field, node.number_in(closed(p.min, p.max))); break;
            case BrdfParam::Kind::colour: material.set_vec3(field, node.vec3_in(kUnit)); break;
            case BrdfParam::Kind::flag: material.set_flag(field, node.boolean()); break;
        }
        return 0;
    });
}

}  // namespace

std::string brdf_without_folder_reason(const std::string& why_none) { return without_folder_reason(kWhat, why_none); }

std::string brdf_not_allowed_reason() {
    return "a .brdf file is code: m3055 batch and grade run it only with --allow-brdf";
}

bool is_brdf_material(const Node& node) {
    return node.value().is_object() && node.has("model") && node.value()["model"] == "brdf";
}

Material read_brdf_material(const Node& node, const SceneFiles& files) {
    node.check_keys({"model", "file", "params", "axis"});
    const Node file_node = node.required("file");
    if (!file_node.value().is_string()) file_node.fail("must be the path of a .brdf file");
    if (!files.context.code_refused.empty()) file_node.fail(files.context.code_refused);
    const io::InputPath file = referenced_file(file_node, files, kWhat);
    const BrdfModel* model = nullptr;
    try {
        model = &load_brdf_model(file);
    } catch (const BrdfError& e) {
        file_node.fail(e.what());
    }
    Material material(*model->spec);
    if (node.has("params")) {
        const Node params = node.child("params");
        params.expect_object();
        std::vector<std::string> names;
        for (const BrdfParam& p : model->file.params) names.push_back(p.name);
        params.check_keys(names, [&](const std::string&) { return "not a parameter of " + model->file.name; });
        for (const BrdfParam& p : model->file.params)
            if (params.has(p.name)) read_value(params.child(p.name), *model, p, material);
    }
    if (node.has("axis")) material.set_vec3("axis", node.child("axis").direction());
    return material;
}

json brdf_material_json(const Material& material, const PathWriting& writing) {
    const BrdfModel* model = find_brdf_model(material.model());
    json params = json::object();
    for (const BrdfParam& p : model->file.params) {
        const std::string field = model->field(p.name);
        switch (p.kind) {
            case BrdfParam::Kind::number: params[p.name] = material.number(field); break;
            case BrdfParam::Kind::colour: {
                const dvec3 c = material.vec3(field);
                params[p.name] = json::array({c.x, c.y, c.z});
                break;
            }
            case BrdfParam::Kind::flag: params[p.name] = material.flag(field); break;
        }
    }
    const dvec3 axis = material.vec3("axis");
    return {{"model", "brdf"},
            {"file", written_path(model->path, writing)},
            {"params", params},
            {"axis", json::array({axis.x, axis.y, axis.z})}};
}

}  // namespace m3055::scene_json
