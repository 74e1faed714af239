// The scanline profile: A's display levels along one row, per
// channel, as a step plot, so the M3055's 32 steps are seen as steps. The
// numbers are renderer/analysis/pixel_probe.h's row_profile of the display
// readback the pixel probe uses.
#pragma once

#include "analysis/pixel_probe.h"

namespace m3055::explore {

// Draws `profile` (nullptr: a note to hover the display) in a box of
// `width` x `height` pixels, the row named above it; hovering a column shows
// its levels. `b` (the A/B split; may be nullptr) is drawn dashed, as in the polar plot.
void profile_plot(const RowProfile* profile, const RowProfile* b, float width, float height);

}  // namespace m3055::explore
