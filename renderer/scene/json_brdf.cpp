#include "scene/json_brdf.h"

#include "brdf_file/brdf_model.h"
#include "models/model_table.h"
#include "scene/load.h"

#include <filesystem>

namespace m3055::scene_json {

namespace {

// Read and rendered from the one thread that renders (models/model_table.h).
std::string g_folder;
bool g_allowed = true;
bool g_confined = false;  // a BrdfConfinement lives
std::string g_root, g_why_none;
std::string g_written_relative_to;  // a BrdfPathsRelativeTo's folder

}  // namespace

std::string brdf_without_folder_reason(const std::string& why_none) {
    return "a .brdf file is not accepted here: " + why_none;
}

namespace {

// The refusal of a .brdf path under a BrdfConfinement, or "" when it may be read.
std::string confinement_problem(const std::string& file, const std::string& resolved) {
    namespace fs = std::filesystem;
    if (g_root.empty()) return brdf_without_folder_reason(g_why_none);
    const fs::path path(file);
    if (path.is_absolute()) return "must be a path inside the submission's folder, not an absolute path";
    for (const fs::path& part : path)
        if (part == "..") return "must be a path inside the submission's folder, without \"..\"";
    std::error_code error;
    const fs::path root = fs::weakly_canonical(g_root, error);
    if (error) return "the submission's folder cannot be resolved: " + error.message();
    const fs::path target = fs::weakly_canonical(resolved, error);
    if (error) return "cannot be resolved: " + error.message();
    // Inside when the root is a prefix of the target, component by component.
    auto r = root.begin(), t = target.begin();
    for (; r != root.end() && t != target.end(); ++r, ++t)
        if (*r != *t) break;
    if (r != root.end() || t == target.end())
        return "leads out of the submission's folder (a symbolic link): a .brdf file must be in it";
    return "";
}

std::string resolve(const std::string& file) {
    const std::filesystem::path path(file);
    if (path.is_absolute() || g_folder.empty()) return file;
    return (std::filesystem::path(g_folder) / path).string();
}

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

BrdfScope::BrdfScope(std::string folder, bool allowed) : old_folder_(g_folder), old_allowed_(g_allowed) {
    g_folder = std::move(folder);
    g_allowed = g_allowed && allowed;
}

BrdfScope::~BrdfScope() {
    g_folder = old_folder_;
    g_allowed = old_allowed_;
}

BrdfPathsRelativeTo::BrdfPathsRelativeTo(std::string folder) : old_folder_(g_written_relative_to) {
    g_written_relative_to = std::move(folder);
}

BrdfPathsRelativeTo::~BrdfPathsRelativeTo() { g_written_relative_to = old_folder_; }

BrdfConfinement::BrdfConfinement(std::string root, std::string why_none)
    : old_active_(g_confined), old_root_(g_root), old_why_none_(g_why_none) {
    g_confined = true;
    g_root = std::move(root);
    g_why_none = std::move(why_none);
}

BrdfConfinement::~BrdfConfinement() {
    g_confined = old_active_;
    g_root = old_root_;
    g_why_none = old_why_none_;
}

void set_brdf_files_allowed(bool allowed) { g_allowed = allowed; }

std::string brdf_not_allowed_reason() {
    return "a .brdf file is code: m3055 batch and grade run it only with --allow-brdf";
}

bool is_brdf_material(const Node& node) {
    return node.value().is_object() && node.has("model") && node.value()["model"] == "brdf";
}

Material read_brdf_material(const Node& node) {
    node.check_keys({"model", "file", "params", "axis"});
    const Node file_node = node.required("file");
    if (!file_node.value().is_string()) file_node.fail("must be the path of a .brdf file");
    if (!g_allowed) file_node.fail(brdf_not_allowed_reason());
    const std::string file = file_node.value().get<std::string>();
    if (g_confined)
        if (const std::string problem = confinement_problem(file, resolve(file)); !problem.empty()) file_node.fail(problem);
    const BrdfModel* model = nullptr;
    try {
        model = &load_brdf_model(resolve(file));
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

namespace {

// The "file" a scene names a .brdf by: absolute, or relative to a
// BrdfPathsRelativeTo's folder when the file is inside it.
std::string written_path(const std::string& path) {
    namespace fs = std::filesystem;
    if (g_written_relative_to.empty()) return fs::absolute(path).string();
    const fs::path full = fs::absolute(path).lexically_normal();
    const fs::path relative = full.lexically_relative(fs::absolute(g_written_relative_to).lexically_normal());
    if (relative.empty() || *relative.begin() == ".." || relative == ".") return full.string();
    return relative.generic_string();
}

}  // namespace

json brdf_material_json(const Material& material) {
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
            {"file", written_path(model->path)},
            {"params", params},
            {"axis", json::array({axis.x, axis.y, axis.z})}};
}

}  // namespace m3055::scene_json
