// Undo/redo of the explorer's state: the steps are explore/history.h's; this
// takes and restores the snapshots, names a step after the operations that
// made it (state.pending, explore/operations.h), and says whether the scene
// differs from its file.
#pragma once

#include "explore/state.h"

#include <string>

namespace m3055::explore {

Snapshot snapshot(const ExplorerState& state);
void restore(ExplorerState& state, const Snapshot& snapshot);
// Forgets the history: `state` is the start (and counts as saved).
void start_history(ExplorerState& state);
// Records the edits since the last commit as one step, named state.pending's
// label (the frame loop calls it when no widget or drag is in progress).
// Returns whether there was one.
bool commit_edits(ExplorerState& state);
bool undo(ExplorerState& state);
bool redo(ExplorerState& state);
// The scene differs from what its file held when last loaded or saved here
// (a scene without a file: from what it started as, e.g. its figure preset):
// undoing back to the saved scene makes it clean again, whichever way it came.
bool unsaved(const ExplorerState& state);
// Records the current scene as what its file (or, without one, its origin) holds.
void mark_saved(ExplorerState& state);
// "NAME" or "NAME * (unsaved edits)" for the title bar.
std::string title_name(const ExplorerState& state);

}  // namespace m3055::explore
