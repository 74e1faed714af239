// Lights in scene files (docs/spec.md#7-scene-files, #75-area-lights-the-sky-and-shadows):
// each light type's own keys, read with validation, and written back (scene_to_json).
#pragma once

#include "scene/json_node.h"
#include "scene/scene.h"

namespace m3055::scene_json {

// Reads and validates one light object; a key of another light type is
// rejected with the types it belongs to ("only for rect and disk lights").
Light read_light(const Node& node);

// The light object scene_to_json writes: exactly the keys read_light accepts
// for its type ("shadow" only when true), so the round trip is exact and a
// scene saved before area lights existed is written as it was.
json light_json(const Light& light);

}  // namespace m3055::scene_json
