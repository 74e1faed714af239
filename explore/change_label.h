// How an edit is named in the Edit menu and the status line: the first value
// that differs between two scenes (or two materials B), as
// explore/operations.cpp's note_edit takes it. Separate so it is tested on
// its own.
#pragma once

#include "explore/pending_edit.h"
#include "scene/scene.h"

namespace m3055::explore {

// The first difference between `before` and `after`: a model switch as
// {"model", OLD, NEW} (" (object I)" added when the scene has several
// objects), a light's field as {"light NAME FIELD", ...} (its index when it
// has no name), any other value by its JSON path ("objects[0].material.m",
// "camera.position"), with the values when it is one number, text or flag.
// Empty when the scenes are equal.
PendingEdit describe_change(const Scene& before, const Scene& after);
// The same for material B: {"B model", OLD, NEW}, {"B NAME", FROM, TO}.
PendingEdit describe_change(const Material& before, const Material& after);

}  // namespace m3055::explore
