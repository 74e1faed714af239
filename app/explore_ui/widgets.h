// Small ImGui helpers for the scene's double-precision fields, so every panel
// uses the same slider behaviour (clamped to the docs/spec.md#7-scene-files ranges, log where the
// parameter spans decades).
#pragma once

#include "explore/slider_scale.h"
#include "models/model_spec.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace m3055::explore {

// A slider on a double; Ctrl+click types a value; Shift while dragging moves
// it a tenth as fast (explore/slider_scale.h). Returns true when changed.
// The result is clamped to [lo, hi], so the scene always stays valid. A
// logarithmic one from lo = 0 spans `decades` below hi.
bool slider_double(const char* label, double* value, double lo, double hi,
                   const char* format = "%.3f", bool logarithmic = false, double decades = kLogSliderDecades);

// A field to type a value into. It shows `shown` until it is typed into;
// what was typed is given back (true, *typed) when the field is left by
// Enter, Tab or a click elsewhere (with `enter_only`, by Enter alone: a
// name), never a half-typed value while typing; Esc restores `shown`.
bool typed_field(const char* label, const std::string& shown, std::string* typed, bool enter_only = false);
// Whole numbers in [lo, hi], one field each on a row (the display's width and
// height), applied as typed_field applies; a text that is not a number changes nothing.
bool typed_ints(const char* label, int* values, int count, int lo, int hi);

// Colour picker for a [0,1]^3 colour.
bool color_edit(const char* label, dvec3* color);

// Up to kMaxLobes (w, m) or (w, n) rows with add/remove, in the ranges of
// `form` (the model table's lobe form: its key, weight and value ranges).
// `min_lobes` = 1 for a material (docs/spec.md#7-scene-files: 1 to 4), 0 for a light's own lobes.
bool lobe_editor(const char* id, std::vector<Lobe>* lobes, const LobeForm& form, int min_lobes);

// A tooltip for the last widget, shown while the mouse is over it and it is
// not being used (a slider's tooltip hides while it is dragged).
void tooltip(const std::string& text);
// Whether the last widget's tooltip may show now (hovered, not held).
bool tooltip_due();

// Grey explanatory text that wraps.
void hint(const char* text);

}  // namespace m3055::explore
