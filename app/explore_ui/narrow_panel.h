// The side panel when it is narrower than its usual kSideWidth (three panes at
// 1:1 at 1280 x 720 leave it 244 px; at 1920 x 1080 one pane at 3x leaves it
// and the plots under it a 376-px column, explore/layout.h): no label or text may
// be cut, so labelled widgets put their label on a line of
// its own above them and take the whole width, and rows of buttons wrap.
// On a panel of the usual width everything is drawn as before (same labels,
// same IDs, same rows).
#pragma once

#include <string>

namespace m3055::explore {

// Set by draw_side_panel each frame (before the sections draw).
void set_narrow_panel(bool narrow);
bool narrow_panel();

// The label to give a labelled widget (slider, combo, input, drag): `label` on
// a wide panel; on a narrow one its visible part (before "##") drawn as a line
// above, the widget set to the whole width, and "##" + label returned.
std::string field(const char* label);
inline std::string field(const std::string& label) { return field(label.c_str()); }

// A combo box's flags: on a narrow panel without the arrow button, so the
// chosen entry (e.g. "metal, Cook-Torrance (eq. 12)") has the whole width.
int combo_flags();

// A checkbox whose label wraps on a narrow panel (a checkbox's own label cannot).
bool checkbox(const char* label, bool* value);

// ImGui::SameLine() when an item `next_width` wide (ImGui units) still fits
// on this row; else the next item starts a row of its own.
void same_line_if_fits(float next_width);
// The width of a button (or small button) labelled `label`.
float button_width(const char* label);

}  // namespace m3055::explore
