// The classic models' materials (SPEC 5, docs/models.md) in scene files:
// reading with validation, and writing back (scene_to_json).
#pragma once

#include "scene/json_node.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace m3055::scene_json {

// The names of the classic models, in the order of Model from Model::lambert.
const std::vector<std::string>& classic_model_names();

// True for a key some classic model reads ("kd", "shininess", ...): on another
// model it is "not a parameter of model X" rather than an unknown key.
bool is_classic_material_key(const std::string& key);

// Reads and validates `node` (the material object) for classic `model`.
Material read_classic_material(const Node& node, Model model);

// The material object scene_to_json writes for a classic model: exactly the
// keys read_classic_material accepts, so the round trip is exact.
json classic_material_json(const Material& material);

}  // namespace m3055::scene_json
