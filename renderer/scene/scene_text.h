// The text of a scene file as people write one (docs/spec.md's examples):
// keys in the spec's order, not nlohmann's alphabetical one (a material's
// parameters in its model's order), and numbers, colours and short objects on
// one line, so a scene the explorer saves reads and diffs like the one it was
// loaded from. Only the layout is chosen here: the value is the one given,
// json::parse(scene_text(j)) == j for every j.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace m3055 {

// `scene`: scene_to_json's object (any JSON value is laid out; keys this file
// does not know keep their alphabetical order, after the known ones). Ends in
// a newline.
std::string scene_text(const nlohmann::json& scene);

}  // namespace m3055
