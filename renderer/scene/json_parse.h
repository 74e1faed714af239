// Scene file text -> JSON document, with errors in the loader's one-line form.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace m3055::scene_json {

// Parses `text`; throws SceneError "SOURCE: invalid JSON: <nlohmann's message>"
// or, for a key given twice in one object (nlohmann would silently keep the
// last), "SOURCE: a.b.key: duplicate key".
nlohmann::json parse_document(const std::string& text, const std::string& source);

}  // namespace m3055::scene_json
