// Batch manifests (`m3055 batch MANIFEST.json`): a JSON array of
// {"scene": "a.json", "out": "a.png", "raw": "a.pfm"} ("raw" optional), paths
// relative to the manifest's own folder. A manifest is as untrusted as the
// scenes it names: it is read and parsed like one (io/input_file.h,
// scene/json_parse.h), and every message is one line naming the entry.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace m3055 {

// A manifest that cannot be used at all; what() names the manifest file and the
// JSON path, e.g. "m.json: [3].out: is required".
class ManifestError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct BatchItem {
    std::size_t entry = 0;        // its index in the manifest
    std::string scene, out, raw;  // joined to the manifest's folder; raw may be empty
    std::string problem;          // why it must be skipped (batch/run_batch.h: check_batch_files), or ""
};

// Reads and validates the whole manifest before anything is rendered, so a
// typo in entry 150 does not cost the 149 renders before it. A path that is
// empty, not a string, or holds a NUL character ("a.json\u0000.evil", which
// the system would read as a.json) is an error naming the entry.
std::vector<BatchItem> load_manifest(const std::string& path);

// The same for manifest text already in memory (`path` names it in messages
// and gives the folder relative paths are joined to); the fuzz target's entry.
std::vector<BatchItem> parse_manifest(const std::string& text, const std::string& path);

}  // namespace m3055
