// --script's read-out commands (`print_compare`, `print_profile`,
// `save_difference PATH`), answered by the frame loop once A (and B) are
// rendered, from the same objects the window draws: a test compares what
// they print and write with headless renders.
#pragma once

#include "explore_ui/compare_view.h"
#include "explore/readouts.h"
#include "explore/state.h"
#include "frame/renderer.h"

namespace m3055::explore {

// Answers and clears state.readout_requests; an impossible one (no split, no
// hovered row) goes to state.error and, as a script error, to stderr.
void answer_readout_requests(ExplorerState& state, Readouts& readouts, Renderer& a, CompareView& compare,
                             Renderer& b);

}  // namespace m3055::explore
