// How an edit is named in the Edit menu and the status line: the first field
// that differs between a part's value before and after, by its path in the
// scene file ("objects[0].material.m 10 -> 40", "light key intensity 1 ->
// 0.5", "camera.position"), with the values when the field is one number,
// choice or flag. Computed from the typed values field by field (the model
// table's parameters for a material), never from the scene as JSON, so
// naming an edit costs what the edited part costs.
#pragma once

#include "explore/edit_values.h"
#include "scene/scene.h"

#include <string>

namespace m3055::explore {

// A field that differs: its path and, for one number, choice or flag, its values before and after.
struct FieldChange {
    std::string what;      // "objects[0].material.m", "light key intensity", "model"
    std::string from, to;  // "" when the field is not one value
    bool empty() const { return what.empty(); }
    // "WHAT FROM -> TO", or "WHAT" when there are no values.
    std::string label() const { return from.empty() && to.empty() ? what : what + " " + from + " -> " + to; }
};

// A value as a label shows it: three significant digits (scientific below
// 1e-3 and from 1e6), so a slider's 1557.0678294 reads 1560.
std::string label_number(double value);

// The first difference of a material, by its key in the material ("m",
// "lobes[1].w"; a model switch: {"model", OLD, NEW}): the caller puts the
// material's path before it ("objects[0].material.m", "B m").
FieldChange material_change(const Material& before, const Material& after);
// A light's first difference, named after the light ("light key intensity"),
// or its index when it has no name ("light 2 intensity").
FieldChange light_change(const Light& before, const Light& after, int index);
// An object's first difference ("objects[2].center"; its material's as
// "objects[2].material.m", a model switch as {"model", OLD, NEW}).
FieldChange object_change(const Object& before, const Object& after, int index);
FieldChange camera_change(const Camera& before, const Camera& after);
FieldChange display_change(const Display& before, const Display& after);

}  // namespace m3055::explore
