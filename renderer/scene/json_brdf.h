// Materials from BRDF Explorer files in scenes:
//   "material": {"model": "brdf", "file": "shiny.brdf", "params": {"roughness": 0.2}, "axis": [0, 1, 0]}
// `file` is relative to the scene file's folder; a parameter left out takes
// the file's default; an unknown name, a wrong type or a value outside the
// file's MIN..MAX is an error naming the scene file, the JSON path and the .brdf.
#pragma once

#include "scene/json_node.h"
#include "models/material.h"

#include <string>

namespace m3055::scene_json {

// While one lives, relative .brdf paths are taken from `folder` (the scene
// file's), and .brdf files are accepted only if `allowed` (m3055 batch without
// --allow-brdf: a .brdf file is code).
class BrdfScope {
public:
    BrdfScope(std::string folder, bool allowed);
    ~BrdfScope();
    BrdfScope(const BrdfScope&) = delete;
    BrdfScope& operator=(const BrdfScope&) = delete;

private:
    std::string old_folder_;
    bool old_allowed_;
};

// While one lives, a .brdf file must resolve, after symbolic links, inside
// `root` (m3055 grade: the submission's own folder): an absolute path, a ".."
// or a link leading out is refused naming the field, before the file is
// opened, so nothing of a file outside the submission reaches a message.
// `root` empty: no .brdf file at all, the refusal ending with `why_none` (a
// submission that is one NAME.json has no folder of its own).
class BrdfConfinement {
public:
    BrdfConfinement(std::string root, std::string why_none);
    ~BrdfConfinement();
    BrdfConfinement(const BrdfConfinement&) = delete;
    BrdfConfinement& operator=(const BrdfConfinement&) = delete;

private:
    bool old_active_;
    std::string old_root_, old_why_none_;
};

// While one lives, brdf_material_json names a .brdf file inside `folder` by
// its path relative to it (the page, app/web/: a saved or shared scene names
// the file as the user named it, not by the page's work folder, so the
// download renders next to the .brdf); a file outside it, and every file with
// none alive, by its absolute path, as before.
class BrdfPathsRelativeTo {
public:
    explicit BrdfPathsRelativeTo(std::string folder);
    ~BrdfPathsRelativeTo();
    BrdfPathsRelativeTo(const BrdfPathsRelativeTo&) = delete;
    BrdfPathsRelativeTo& operator=(const BrdfPathsRelativeTo&) = delete;

private:
    std::string old_folder_;
};

// A BrdfConfinement's refusal with no folder: "a .brdf file is not accepted
// here: " + why_none (m3055 explore --assignment --allow-brdf gives it for a
// scene that is one file, as grade does).
std::string brdf_without_folder_reason(const std::string& why_none);
// Why a submission that is one NAME.json may not hold a .brdf material
// (grade_run.cpp's BrdfConfinement, practice.cpp).
inline constexpr const char* kBrdfNeedsAFolder =
    "a submission with a .brdf material is a folder NAME/ holding scene.json and the .brdf file";

// The refusal when .brdf files are not accepted (m3055 explore --assignment
// gives the same reason for a scene whose material comes from one).
std::string brdf_not_allowed_reason();

// Whether .brdf materials are accepted outside any scope (the default: yes).
void set_brdf_files_allowed(bool allowed);

bool is_brdf_material(const Node& node);  // its "model" is "brdf"
Material read_brdf_material(const Node& node);
json brdf_material_json(const Material& material);  // {"model": "brdf", "file", "params", "axis"}

}  // namespace m3055::scene_json
