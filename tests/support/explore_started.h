// The explorer's state as `m3055 explore` with no arguments starts it: the spec
// example, its undo history begun (nothing unsaved). For the explorer's unit
// tests (tests/explore_*_test.cpp, which link m3055_explore).
#pragma once

#include "explore/files.h"
#include "explore/state.h"
#include "explore/undo.h"
#include "scene/presets.h"

namespace m3055::explore::test {

inline ExplorerState started() {
    ExplorerState state;
    set_scene(state, default_scene(), "spec example");
    start_history(state);
    return state;
}

}  // namespace m3055::explore::test
