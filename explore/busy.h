// What the explorer is busy with, for the line beside the menu: "reloading FILE..." between noticing a changed .brdf file and
// reloading it (a frame shows it first: explore/brdf_files.h), "compiling..."
// while a model's own program waits to be built (the display meanwhile draws
// with the general program, the same pixels: explore/display_renderers.h),
// "refining..." while a preview of area lights waits to be drawn again with
// the render's samples (explore/display_renderers.h).
#pragma once

#include "explore/session.h"

#include <cstddef>
#include <string>

namespace m3055::explore {

// "" when idle; `deferred`: programs waiting to be compiled; `refining`: the
// display shows a preview of area lights, not yet the render's pixels.
std::string busy_line(const BrdfWatch& watch, std::size_t deferred, bool refining = false);

}  // namespace m3055::explore
