// The rules for the files a scene names besides itself (a material's .brdf
// file; each kind is read through scene/referenced_file.h), passed to every
// load and every write of a scene, so that a call says what it allows.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>

namespace m3055 {

// A folder every file a scene names must stay inside, symbolic links
// followed: an absolute path, a ".." or a link leading out is refused before
// the file is opened, so nothing of a file outside reaches a message. Its one
// use is `m3055 grade`'s submission folder, which the messages name so.
struct Confinement {
    std::string root;      // relative to LoadContext::folder; "": no named file at all
    std::string why_none;  // the refusal's reason when `root` is ""
};

struct LoadContext {
    // Relative paths (the scene file's, and through its folder those it names)
    // are taken from here, "" the working folder; messages name them as
    // written (m3055 grade: the class folder, so they say "alice/scene.json").
    std::string folder;
    // Why a file of code (a .brdf material: its GLSL runs) is refused; "": accepted.
    std::string code_refused;
    std::optional<Confinement> confinement;
    // Where a load's notes go (what a file holds that is ignored: a model's
    // textures), one line each; unset: stderr, as "m3055: note: LINE".
    std::function<void(const std::string&)> note;

    // The user's own files: from the working folder, code accepted, not confined.
    static LoadContext trusted();
    // A class's scenes (m3055 batch and grade): as trusted(), but a .brdf
    // material only when the teacher allows code (--allow-brdf).
    static LoadContext for_class(bool allow_code);
};

// How a written scene (scene_to_json) names the files it references.
struct PathWriting {
    // "": by absolute paths; else a file inside this folder by its path
    // relative to it (the page, app/web/: the user's own names, so a download
    // renders next to its files), one outside it absolutely.
    std::string relative_to;
    // Model files (a mesh's "file") relative to this folder instead, "" as
    // relative_to: the desktop explorer names them from the saved scene's
    // folder, so a scene saved beside its model renders where it is moved.
    std::string model_files_relative_to;

    static PathWriting absolute() { return {}; }
    static PathWriting relative_to_folder(std::string folder) { return {std::move(folder), {}}; }
};

}  // namespace m3055
