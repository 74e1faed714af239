// The explorer as `m3055 explore` with no arguments starts it: the spec
// example, its undo history begun (nothing unsaved); and a command given as a
// widget, key or script gives it, applied at once. For the explorer's unit
// tests (tests/explore_*_test.cpp, which link m3055_explore).
#pragma once

#include "explore/apply.h"
#include "explore/explorer.h"
#include "explore/files.h"
#include "explore/start.h"
#include "scene/presets.h"

namespace m3055::explore::test {

inline Explorer started() {
    Explorer explorer;
    set_scene(explorer, default_scene(), "spec example");
    start_history(explorer);
    return explorer;
}

// `command` given now (after any already queued) and applied; its outcome.
inline bool run(Explorer& explorer, Command command) { return run_command(explorer, std::move(command)); }

}  // namespace m3055::explore::test
