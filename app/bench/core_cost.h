// `m3055 bench --latency`'s explorer core section: what the explorer's logic
// costs a slider tick and an idle frame (no GL: the command applied, the edit
// named and recorded, the undo step, the title's "unsaved edits") in scenes
// of 10, 1 000 and 100 000 objects. Drawing the scene is the renderer's and
// grows with it; this part should not.
#pragma once

#include <string>
#include <vector>

namespace m3055::bench {

struct CoreCost {
    int objects = 0;
    double tick_us = 0;    // median: one slider value given and applied (SetMaterial, named, merged into the drag)
    double frame_us = 0;   // median: an idle frame's logic (queue, commit, title, busy line, watched files)
    double commit_us = 0;  // median: the drag's end made an undo step
    double undo_us = 0;    // median: Ctrl+Z of that step
};

struct CoreCostReport {
    std::vector<CoreCost> rows;
    std::string markdown() const;
};

CoreCostReport explorer_core_cost();

}  // namespace m3055::bench
