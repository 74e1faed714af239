#include "scene/referenced_file.h"

#include <filesystem>

namespace m3055::scene_json {

namespace fs = std::filesystem;

namespace {

// The refusal of `file` (as the scene wrote it, opened at `opened`) under
// `confinement`, or "" when it may be read.
std::string confinement_problem(const Confinement& confinement, const std::string& folder, const std::string& file,
                                const std::string& opened, const std::string& what) {
    if (confinement.root.empty()) return without_folder_reason(what, confinement.why_none);
    const fs::path path(file);
    if (path.is_absolute()) return "must be a path inside the submission's folder, not an absolute path";
    for (const fs::path& part : path)
        if (part == "..") return "must be a path inside the submission's folder, without \"..\"";
    std::error_code error;
    const fs::path root = fs::weakly_canonical(io::InputPath::in_folder(folder, confinement.root).path, error);
    if (error) return "the submission's folder cannot be resolved: " + error.message();
    const fs::path target = fs::weakly_canonical(opened, error);
    if (error) return "cannot be resolved: " + error.message();
    // Inside when the root is a prefix of the target, component by component.
    auto r = root.begin(), t = target.begin();
    for (; r != root.end() && t != target.end(); ++r, ++t)
        if (*r != *t) break;
    if (r != root.end() || t == target.end())
        return "leads out of the submission's folder (a symbolic link): " + what + " must be in it";
    return "";
}

}  // namespace

std::string without_folder_reason(const std::string& what, const std::string& why_none) {
    return what + " is not accepted here: " + why_none;
}

io::InputPath referenced_file(const Node& node, const SceneFiles& files, const std::string& what) {
    const std::string file = node.value().get<std::string>();
    const fs::path path(file);
    const std::string named =
        path.is_absolute() || files.scene_folder.empty() ? file : (fs::path(files.scene_folder) / path).string();
    const io::InputPath found = io::InputPath::in_folder(files.context.folder, named);
    if (const auto& confinement = files.context.confinement)
        if (const std::string problem = confinement_problem(*confinement, files.context.folder, file, found.path, what);
            !problem.empty())
            node.fail(problem);
    return found;
}

io::InputPath referenced_by_file(const std::string& name, const io::InputPath& parent, const SceneFiles& files,
                                 const std::string& what, std::string& problem) {
    const fs::path path(name);
    const fs::path folder = fs::path(parent.shown).parent_path();
    const std::string named = path.is_absolute() || folder.empty() ? name : (folder / path).string();
    const io::InputPath found = io::InputPath::in_folder(files.context.folder, named);
    problem.clear();
    if (const auto& confinement = files.context.confinement)
        problem = confinement_problem(*confinement, files.context.folder, name, found.path, what);
    return found;
}

std::string written_path(const std::string& path, const PathWriting& writing) {
    if (writing.relative_to.empty()) return fs::absolute(path).string();
    const fs::path full = fs::absolute(path).lexically_normal();
    const fs::path relative = full.lexically_relative(fs::absolute(writing.relative_to).lexically_normal());
    if (relative.empty() || *relative.begin() == ".." || relative == ".") return full.string();
    return relative.generic_string();
}

}  // namespace m3055::scene_json
