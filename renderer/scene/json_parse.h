// Scene file text -> JSON document, with errors in the loader's one-line form.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace m3055::scene_json {

// Files and --set values may nest at most this deep (the format itself needs 6
// levels). Deeper input is rejected before anything walks it recursively:
// nlohmann's dump(), which error messages use, recurses once per level, and a
// 400 KB file of '[' overflowed the stack.
inline constexpr std::size_t kMaxNesting = 64;

// Parses `text`; throws SceneError "SOURCE: invalid JSON: <nlohmann's message>"
// or, for a key given twice in one object (nlohmann would silently keep the
// last), "SOURCE: a.b.key: duplicate key"; nesting beyond kMaxNesting is
// "SOURCE: a.b[0]...: nested deeper than 64 levels".
nlohmann::json parse_document(const std::string& text, const std::string& source);

}  // namespace m3055::scene_json
