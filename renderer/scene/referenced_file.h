// A file a scene names in one of its fields (a .brdf material's "file"):
// found from the scene file's folder under the load's rules
// (scene/load_context.h), and named again when the scene is written. Every
// kind of named file goes through here, so each obeys the same confinement.
#pragma once

#include "io/input_path.h"
#include "scene/json_node.h"
#include "scene/load_context.h"

#include <string>

namespace m3055::scene_json {

// Where the files a scene names are: the load's rules, and the scene file's
// folder as messages name it (relative to LoadContext::folder; "" for a
// scene read from no file).
struct SceneFiles {
    const LoadContext& context;
    std::string scene_folder;
};

// The file that `node`, a string field, names relative to the scene's folder:
// where it is opened and how messages name it. Under a confinement a path
// leading out fails `node` (SceneError) before anything is opened; `what`
// names the kind of file in that refusal ("a .brdf file").
io::InputPath referenced_file(const Node& node, const SceneFiles& files, const std::string& what);

// A file that a named file names in turn (a model file's .mtl or .bin):
// `name` relative to the folder of `parent` (found by referenced_file), under
// the same confinement. Sets `problem` to the refusal, before anything is
// opened, when it may not be read.
io::InputPath referenced_by_file(const std::string& name, const io::InputPath& parent, const SceneFiles& files,
                                 const std::string& what, std::string& problem);

// The refusal under a confinement without a folder: "WHAT is not accepted here: WHY_NONE".
std::string without_folder_reason(const std::string& what, const std::string& why_none);

// The path a written scene names a file by, `path` being where it was read.
std::string written_path(const std::string& path, const PathWriting& writing);

}  // namespace m3055::scene_json
