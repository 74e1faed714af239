// Materials from BRDF Explorer files in scenes:
//   "material": {"model": "brdf", "file": "shiny.brdf", "params": {"roughness": 0.2}, "axis": [0, 1, 0]}
// `file` is relative to the scene file's folder; a parameter left out takes
// the file's default; an unknown name, a wrong type or a value outside the
// file's MIN..MAX is an error naming the scene file, the JSON path and the .brdf.
#pragma once

#include "scene/json_node.h"
#include "scene/referenced_file.h"
#include "models/material.h"

#include <string>

namespace m3055::scene_json {

// The refusal under a confinement without a folder: "a .brdf file is not
// accepted here: " + why_none (m3055 explore --assignment --allow-brdf gives
// it for a scene that is one file, as grade does).
std::string brdf_without_folder_reason(const std::string& why_none);
// Why a submission that is one NAME.json may name no file, a .brdf material's
// or a model's (grade_run.cpp's confinement, practice.cpp).
inline constexpr const char* kFilesNeedAFolder =
    "a submission that names a file (a .brdf material, a model) is a folder NAME/ holding scene.json and the file";

// The refusal when .brdf files are not accepted (LoadContext::for_class;
// m3055 explore --assignment gives the same reason for a scene whose
// material comes from one).
std::string brdf_not_allowed_reason();

bool is_brdf_material(const Node& node);  // its "model" is "brdf"
// `files`: where the .brdf is found, and whether it may be (scene/referenced_file.h).
Material read_brdf_material(const Node& node, const SceneFiles& files);
// {"model": "brdf", "file", "params", "axis"}, "file" written as `writing` says.
json brdf_material_json(const Material& material, const PathWriting& writing);

}  // namespace m3055::scene_json
