// The limits on model files (docs/limits.md#model-files).
#pragma once

#include <cstddef>

namespace m3055::model_file {

// A model file and each file it names: a 1 000 000-triangle OBJ with normals
// is about 80 MB, the scene's 4 000 000 triangles as a .glb about 100 MB.
inline constexpr std::size_t kMaxModelBytes = std::size_t(256) << 20;
// Nesting of a glTF's JSON (tinygltf's parse recurses into "extras").
inline constexpr int kMaxJsonDepth = 64;
// Nodes above nodes in a glTF scene.
inline constexpr int kMaxNodeDepth = 64;
// A file without normals gets smooth normals except across edges whose faces
// meet at more than this (docs/shapes.md#meshes-from-files).
inline constexpr double kCreaseAngleDeg = 30.0;

}  // namespace m3055::model_file
