// Scene file text -> JSON document, with errors in the loader's one-line form.
// Also used for batch manifests (scene/manifest.h): both are untrusted files.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace m3055::scene_json {

// Files and --set values may nest at most this deep (the format itself needs 6
// levels). Deeper input is rejected before anything walks it recursively:
// nlohmann's dump(), which error messages use, recurses once per level, and a
// 400 KB file of '[' overflowed the stack.
inline constexpr std::size_t kMaxNesting = 64;
// Keys one object may have. The formats' objects have at most a few dozen, so
// a larger one is an error anyway; the cap keeps the duplicate-key check's
// memory small whatever the input.
inline constexpr std::size_t kMaxKeys = 256;
// Memory the parsed document (nlohmann::json) may take, estimated before it is
// built. A 16 MiB file of "{}," would take 600 MB as a document: it is rejected
// first, using next to nothing. The largest scene the format allows (100 000
// objects) takes less than this.
inline constexpr std::size_t kMaxDocumentBytes = std::size_t(192) << 20;

// What one pass over `text` found, before any document is built: `problem`
// is "" or the message without the source; `document_bytes` the estimated
// memory of the parsed document (exact for the containers, tested in
// tests/json_parse_test.cpp), as far as the pass counted.
struct DocumentScan {
    std::string problem;
    std::size_t document_bytes = 0;
};
DocumentScan scan_document(const std::string& text);

// Parses `text`; throws SceneError:
//   "SOURCE: invalid JSON: <nlohmann's message, its quoted token cut>"
//   "SOURCE: is UTF-16 text ..." / "SOURCE: holds a NUL byte at byte N ..."
//   "SOURCE: a.b.key: duplicate key" (nlohmann would silently keep the last)
//   "SOURCE: a.b[0]...: nested deeper than 64 levels"
//   "SOURCE: a.b: has more than 256 keys"
//   "SOURCE: too large: ... more than 192 MiB ..."
// Syntax errors win over the others, as when the document was parsed first.
nlohmann::json parse_document(const std::string& text, const std::string& source);

}  // namespace m3055::scene_json
