#include "scene/json_model_file.h"

#include "io/input_file.h"
#include "io/message_text.h"
#include "model_file/model_limits.h"
#include "scene/json_material.h"
#include "scene/load.h"
#include "scene/shape_limits.h"

#include <algorithm>
#include <cstdio>
#include <set>

namespace m3055::scene_json {

namespace {

constexpr const char* kModelFileWhat = "a model file";
constexpr const char* kSideFileWhat = "a file a model names";

std::string unit_range_problem(const std::string& key, double value) {
    return key + " must be in [0, 1], got " + format_number(value);
}

bool unit(double v) { return v >= 0.0 && v <= 1.0; }
bool unit(const dvec3& v) { return unit(v.x) && unit(v.y) && unit(v.z); }

// The model file `file_node` names, loaded (or the one line why not).
std::shared_ptr<const model_file::Model> load_model(const Node& file_node, const SceneFiles& files,
                                                    std::string& opened, std::string& shown) {
    if (!file_node.value().is_string()) file_node.fail("must be the path of a model file (.obj, .gltf or .glb)");
    const io::InputPath found = referenced_file(file_node, files, kModelFileWhat);
    opened = found.path;
    shown = text::quote_name(found.shown);
    try {
        const model_file::Format format = model_file::format_of(found.shown);
        const std::string bytes = io::read_input_file(found, model_file::kMaxModelBytes);
        std::vector<std::string> side_files;
        const model_file::SideFileReader side = [&](const std::string& name) {
            std::string problem;
            const io::InputPath side_file = referenced_by_file(name, found, files, kSideFileWhat, problem);
            if (!problem.empty()) throw model_file::ModelError(text::quote_name(name) + ": " + problem);
            std::string content;
            try {
                content = io::read_input_file(side_file, model_file::kMaxModelBytes);
            } catch (const io::InputError& e) {
                throw model_file::ModelError(e.what());
            }
            if (std::find(side_files.begin(), side_files.end(), name) == side_files.end()) side_files.push_back(name);
            return content;
        };
        auto model = std::make_shared<model_file::Model>(
            model_file::parse_model(bytes, format, side, kMaxSceneTriangles));
        model->side_files = std::move(side_files);
        for (const std::string& note : model->notes) {
            const std::string line = file_node.source() + ": " + file_node.path() + ": " + shown + ": " + note;
            if (files.context.note) files.context.note(line);
            else std::fprintf(stderr, "m3055: note: %s\n", line.c_str());
        }
        return model;
    } catch (const io::InputError& e) {
        file_node.fail(e.what());
    } catch (const model_file::ModelError& e) {
        file_node.fail(shown + ": " + e.what());
    } catch (const std::bad_alloc&) {
        file_node.fail(shown + ": too large to load");
    }
}

// "materials": {"NAME": {...}}: a whole material (with "model"), or the
// file's own material of that name with the parameters given changed.
Material read_override(const Node& node, const SceneFiles& files, const Material& own) {
    node.expect_object();
    if (node.has("model")) return read_material(node, files);
    json merged = material_json(own, PathWriting::absolute());
    for (const auto& [key, value] : node.value().items()) merged[key] = value;
    return read_material(Node(merged, node.path(), node.source()), files);
}

std::string listed_names(const std::vector<GroupMaterial>& groups) {
    std::set<std::string> names;
    for (const GroupMaterial& g : groups) names.insert(g.name);
    std::string out;
    std::size_t shown = 0;
    for (const std::string& name : names) {
        if (shown == 5) return out + ", ...";
        out += (shown++ ? ", " : "") + text::quote(name);
    }
    return out;
}

}  // namespace

Material material_from_file(const model_file::FileMaterial& m, std::string& problem) {
    problem.clear();
    using Kind = model_file::FileMaterial::Kind;
    if (m.kind == Kind::gltf) {
        Material out = Material::of("principled");
        if (!unit(m.base_color)) problem = "baseColorFactor must be in [0, 1]";
        else if (!unit(m.metallic)) problem = unit_range_problem("metallicFactor", m.metallic);
        else if (!unit(m.roughness)) problem = unit_range_problem("roughnessFactor", m.roughness);
        if (!problem.empty()) return out;
        out.set_vec3("base_color", m.base_color);
        out.set_vec3("ka", m.base_color);
        out.set_number("metallic", m.metallic);
        out.set_number("roughness", m.roughness);
        return out;
    }
    Material out = Material::of("phong");
    if (m.kind == Kind::none) return out;
    if (!unit(m.kd)) problem = "Kd must be in [0, 1]";
    else if (!unit(m.ks)) problem = "Ks must be in [0, 1]";
    else if (!(m.ns >= 0.0 && m.ns <= 10000.0)) problem = "Ns must be in [0, 10000], got " + format_number(m.ns);
    if (!problem.empty()) return out;
    out.set_vec3("kd", m.kd);
    out.set_vec3("ka", m.kd);
    out.set_vec3("ks", m.ks);
    out.set_number("shininess", m.ns);
    return out;
}

void read_mesh_file(const Node& node, const SceneFiles& files, Object& object) {
    const Node file_node = node.required("file");
    std::string shown;
    object.model = load_model(file_node, files, object.file, shown);
    if (node.has("material") && node.has("materials"))
        node.child("materials").fail("give \"material\" (the whole model's) or \"materials\" (by the file's names), not both");
    if (node.has("material")) {
        object.material = read_material(node.child("material"), files);
        return;
    }
    for (const model_file::FileMaterial& m : object.model->materials) {
        GroupMaterial group;
        group.name = m.name;
        object.groups.push_back(group);
    }
    std::set<std::string> overridden;
    if (node.has("materials")) {
        const Node materials = node.child("materials");
        materials.expect_object();
        for (const auto& [name, value] : materials.value().items()) {
            bool found = false;
            for (const GroupMaterial& g : object.groups) found = found || g.name == name;
            if (!found)
                materials.child(name).fail("the model file has no material of this name (its materials: " +
                                           listed_names(object.groups) + ")");
            overridden.insert(name);
        }
    }
    for (std::size_t i = 0; i < object.groups.size(); ++i) {
        GroupMaterial& group = object.groups[i];
        std::string problem;
        const Material own = material_from_file(object.model->materials[i], problem);
        if (overridden.count(group.name)) {
            group.material = read_override(node.child("materials").child(group.name), files, own);
            group.overridden = true;
            continue;
        }
        if (!problem.empty())
            file_node.fail(shown + ": material " + text::quote(group.name) + ": " + problem +
                           " (give the object a \"material\", or this one in \"materials\")");
        group.material = own;
    }
    object.material = object.groups.front().material;
}

void write_mesh_file(const Object& object, const PathWriting& writing, json& entry) {
    const std::string& models_folder = writing.model_files_relative_to;
    entry["file"] = written_path(object.file, models_folder.empty() ? writing : PathWriting{models_folder, {}});
    if (object.groups.empty()) {
        entry["material"] = material_json(object.material, writing);
        return;
    }
    json materials = json::object();
    for (const GroupMaterial& group : object.groups)
        if (group.overridden) materials[group.name] = material_json(group.material, writing);
    if (!materials.empty()) entry["materials"] = std::move(materials);
}

}  // namespace m3055::scene_json
