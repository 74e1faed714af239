// A modal dialog with one path field, as File > Open BRDF and File > Add
// model have: opened when the view asks for its Dialog (in the page, the
// browser's file chooser opens instead), the field focused, Enter or the OK
// button runs the action, the last error in red under the field, Esc or
// Cancel closes it.
#pragma once

#include "explore/explorer.h"

#include <functional>
#include <string>

namespace m3055::explore {

struct PathDialog {
    const char* title;     // the window's title, also its ImGui id
    Dialog dialog;         // the view's request that opens it
    std::string text;      // the line above the field
    const char* ok;        // the button that runs `run`
    std::string* path;     // the field (kept in the view between openings)
    std::string* error;    // the message shown in red; cleared when the dialog opens
    std::function<bool()> run;             // true: done, the dialog closes
    std::function<void()> cancelled = {};  // after Esc or Cancel
};

void path_dialog(Explorer& explorer, const PathDialog& dialog);

}  // namespace m3055::explore
