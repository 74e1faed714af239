// Materials in scene files, driven by the model table: every model's keys,
// ranges, defaults and misplaced-key messages come from its ModelSpec
// (models/builtin_models.cpp), so reading and writing need no per-model code.
#pragma once

#include "scene/json_node.h"
#include "scene/referenced_file.h"
#include "models/material.h"

namespace m3055::scene_json {

// Reads and validates a material object ({"model": ..., its parameters}).
// Errors: "SOURCE: objects[0].material.KEY: problem". A .brdf material's
// file is found and allowed as `files` says.
Material read_material(const Node& node, const SceneFiles& files);

// The material object scene_to_json writes: exactly the keys read_material
// accepts for its model, so the round trip is exact; a .brdf material's file
// named as `writing` says.
json material_json(const Material& material, const PathWriting& writing);

}  // namespace m3055::scene_json
