// A mesh from a model file in scene files (docs/shapes.md#meshes-from-files):
//   {"shape": "mesh", "file": "model.obj", "center": C, "size": s,
//    "rotation_deg": [rx, ry, rz], "material": {...} | "materials": {"NAME": {...}}}
// `file` is a referenced file (scene/referenced_file.h), and so are the files
// it names (an OBJ's .mtl, a glTF's .bin): found and confined alike. Without
// "material" each of the file's materials becomes one of the table's
// (phong from an OBJ's Kd, Ks, Ns; principled from a glTF's base colour,
// metallic, roughness), "materials" overriding them by the file's names.
#pragma once

#include "scene/json_node.h"
#include "scene/referenced_file.h"

namespace m3055::scene_json {

// Reads "file" (the model, loaded and checked), "material" or "materials"
// of mesh object `node` into `object` (its shape's other keys: read_shape).
void read_mesh_file(const Node& node, const SceneFiles& files, Object& object);

// "file" and "material" or "materials" as scene_to_json writes them into
// `entry`: the file named as `writing` says, only the overrides written.
void write_mesh_file(const Object& object, const PathWriting& writing, json& entry);

// The file's own material as one of the table's (phong or principled), or
// the problem ("Kd must be in [0, 1], got 1.5") when a value is out of range.
Material material_from_file(const model_file::FileMaterial& material, std::string& problem);

}  // namespace m3055::scene_json
