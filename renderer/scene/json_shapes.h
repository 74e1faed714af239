// The shapes of scene objects (docs/shapes.md) in scene files: each shape's
// own keys, read with validation, and written back (scene_to_json).
#pragma once

#include "scene/json_node.h"
#include "scene/scene.h"

namespace m3055::scene_json {

// Reads the geometry keys of object `node` (everything but "material") into
// `object`; rejects the keys of other shapes with the shapes they belong to.
void read_shape(const Node& node, Object& object);

// The object's geometry keys as scene_to_json writes them ("shape" included,
// "material" not): exactly what read_shape accepts, so the round trip is exact.
json shape_json(const Object& object);

}  // namespace m3055::scene_json
