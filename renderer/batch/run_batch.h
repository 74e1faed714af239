// `m3055 batch`: many scenes in one process, through one Capture; the
// manifest format is in scene/manifest.h.
#pragma once

#include "capture/capture.h"
#include "scene/load_context.h"
#include "scene/manifest.h"

#include <functional>
#include <string>
#include <vector>

namespace m3055 {

// Checks every file the run reads and writes together, before anything is
// written (io/run_files.h): an output that is the manifest, a scene, or
// another output, or that is not a regular file, or whose folder is missing,
// sets the item's `problem` (both items of a clash), naming both entries.
// `manifest` may be empty when the items come from elsewhere; `report`, when
// not empty, is one more output of the run (`batch --report`).
void check_batch_files(std::vector<BatchItem>& items, const std::string& manifest, const std::string& report = "");

// Called after each item: index (0-based), item, and the error line ("" on success).
using BatchProgress = std::function<void(std::size_t index, const BatchItem& item, const std::string& error)>;

struct BatchOptions {
    unsigned encoder_threads = 0;  // 0: one per core
    double scene_timeout_s = 0;    // each scene's time budget (capture/capture.h: scene_deadline); 0: none
    // Bytes of finished images (display, PNG, raw floats) waiting to be
    // written; a scene is read back only when its images fit beside them, or
    // when none are waiting (docs/limits.md: the memory bound of batch).
    std::size_t image_memory_budget = std::size_t(512) << 20;
    // Runs under the file-commit lock each time an item's files are all in
    // place (app/interrupt.h counts them there, so its count is exact).
    std::function<void()> on_written;
    // Called (on the rendering thread) for a scene whose render has NaN or
    // infinite pixels, with the warning line (capture/capture.h: nonfinite_warning);
    // the scene is written all the same and does not count as failed.
    std::function<void(std::size_t index, const BatchItem& item, const std::string& warning)> warned;
};

// Renders every item with one context and renderer, made by `capture` when
// the first scene is drawn (never, when no scene loads); each scene is loaded
// as `scenes` allows (LoadContext::for_class). First every scene is
// loaded once without a context: an item with a `problem`, or whose scene
// fails to load, is reported then (so every such line comes first, and a
// hostile scene costs only its own loading). Then the rest are rendered in
// manifest order; a scene over its time budget or failing to render or write
// is reported and skipped. Returns the number of failed items.
// Rendering stays on this thread (the GL context is current here); PNG/PFM
// encoding and writing, which cost more than rendering a 512 x 320 frame on
// llvmpipe, run on encoder threads while the next scene renders, bounded by
// image_memory_budget. An interrupt ends the process wherever it is
// (app/interrupt.h).
std::size_t run_batch(const std::function<Capture&()>& capture, const std::vector<BatchItem>& items,
                      const LoadContext& scenes, const BatchProgress& progress, const BatchOptions& options = {});

}  // namespace m3055
