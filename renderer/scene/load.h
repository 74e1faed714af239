// Scene loading: JSON (docs/spec.md#7-scene-files) -> validated Scene.
// Every error names the file and the JSON path, e.g.
//   scene.json: objects[0].material.m: must be in [0, 10000], got -3
#pragma once

#include "scene/load_context.h"
#include "scene/scene.h"

#include <nlohmann/json_fwd.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace m3055 {

// Thrown for any invalid input; what() is the one-line message to print.
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A `--set path=value` override, e.g. "objects[0].material.m=40". The value is
// parsed as JSON when it is valid JSON, otherwise taken as a string.
struct Override {
    std::string path;   // objects[0].material.m
    std::string value;  // 40
};

// Parses "path=value"; throws SceneError naming the text when malformed.
Override parse_override(const std::string& text);

// Applies overrides to a parsed JSON document (creating the leaf key if absent;
// intermediate objects/arrays must exist). `source` names the file in errors.
void apply_overrides(nlohmann::json& doc, const std::vector<Override>& overrides,
                     const std::string& source);

// The loader's `error` about a document with `overrides` applied, blamed on the
// override that set the field it names ("F: --set lights[0].intensity: lights[0].intensity:
// must be a number, got \"abc\""), or noted where an override of its object's kind (type,
// projection, shape, model) made a field of the file wrong; `error` itself otherwise.
SceneError blame_override(const SceneError& error, const std::vector<Override>& overrides, const std::string& source);

// Validates a JSON document and builds the Scene. `source` is the file name used
// as the prefix of error messages; the files the scene names are relative to
// `context.folder` and read as `context` allows (scene/load_context.h).
Scene scene_from_json(const nlohmann::json& doc, const std::string& source, const LoadContext& context);
// The same after `overrides` (apply_overrides), a problem they made blamed on them (blame_override).
Scene scene_from_json(nlohmann::json doc, const std::vector<Override>& overrides, const std::string& source,
                      const LoadContext& context);

// Reads, applies overrides, validates. `path` and the files the scene names
// (relative to the scene file's folder) are read as `context` says. Throws
// SceneError on any problem (unreadable file, invalid JSON, validation
// failure, a named file refused).
Scene load_scene_file(const std::string& path, const LoadContext& context, const std::vector<Override>& overrides = {});

// Serializes a Scene back to JSON in the docs/spec.md#7-scene-files format (round-trips
// through scene_from_json), the files it names written as `writing` says.
nlohmann::json scene_to_json(const Scene& scene, const PathWriting& writing);

}  // namespace m3055
