// `m3055 batch`: many scenes in one process (issue 4, "Batch capture").
// The manifest is a JSON array of {"scene": "a.json", "out": "a.png", "raw": "a.pfm"}
// ("raw" optional), paths relative to the manifest's own folder.
#pragma once

#include "capture.h"

#include <functional>
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
    std::string scene, out, raw;  // resolved against the manifest's folder; raw may be empty
};

// Reads and validates the whole manifest before anything is rendered, so a
// typo in entry 150 does not cost the 149 renders before it.
std::vector<BatchItem> load_manifest(const std::string& path);

// Called after each item: index (0-based), item, and the error line ("" on success).
using BatchProgress = std::function<void(std::size_t index, const BatchItem& item, const std::string& error)>;

// Renders every item with one context and renderer. A scene that fails to load
// or render is reported through `progress` and skipped. Returns the number of
// failed items. Rendering stays on this thread (the GL context is current
// here); PNG/PFM encoding and writing, which cost more than rendering a
// 512 x 320 frame on llvmpipe, run on `encoder_threads` workers while the next
// scene renders (0: one per core). Progress is reported in manifest order.
// `stop` (e.g. Ctrl-C, app/interrupt.h) is asked before each scene: once true,
// no further scene is started, and the writes already under way complete.
std::size_t run_batch(Capture& capture, const std::vector<BatchItem>& items, const BatchProgress& progress,
                      unsigned encoder_threads = 0, const std::function<bool()>& stop = {});

}  // namespace m3055
