// GLSL generated from the model table, so that no model is named by hand in
// glsl/common/: the MODEL_* and FAMILY_* ids, the choice constants
// (DISTRIBUTION_GGX ...), struct Material with a field per parameter,
// fetch_material (one unpacking branch per model, under its HAS_* define),
// the includes of the models' GLSL files and each family's dispatcher to the
// models' hooks. glsl/models/shade.glsl includes the two files:
//   "generated/material.glsl"  ids, struct Material, fetch_material, prototypes
//   "generated/models.glsl"    the models' files and the dispatchers
#pragma once

#include "models/glsl_sources.h"

#include <string>
#include <vector>

namespace m3055 {

struct ModelSpec;
class ModelTable;

// Texels per row of the material records' 2D texture (passes/material_texture.h,
// fetch_material): WebGL2 guarantees textures of 2048 texels a side, and
// 2048 rows of 2048 texels hold 100000 objects' records many times over.
inline constexpr int kMaterialTextureWidth = 2048;

// The generated files for `table` (their paths as above). `glsl_es`: the
// entries' GLSL ES sources where they have them (ModelSpec::glsl_sources_es).
std::vector<std::pair<std::string, std::string>> generate_glsl(const ModelTable& table, bool glsl_es = false);

// The same for the process's table, regenerated when its revision changes.
// Returned by value: a run-time model added later does not invalidate it.
std::vector<std::pair<std::string, std::string>> generated_glsl(bool glsl_es = false);

// The HAS_* define of a model, and of a family of models.
std::string has_define(const ModelSpec& model);
std::string family_define(int family);

// All HAS_* and family defines: what a general program (every model) compiles with.
std::vector<std::string> every_model_define(const ModelTable& table);

}  // namespace m3055
