// What the edits since the last undo step did: the next step's label, e.g.
// "objects[0].material.m 10 -> 40" or "model metal -> half_lambert". A slider
// dragged over many frames is one step: its label keeps the value the drag
// started from and the one it ended at.
#pragma once

#include <string>

namespace m3055::explore {

struct PendingEdit {
    std::string what;      // "objects[0].material.m", "model", "light key intensity", "figure preset fig06"
    std::string from, to;  // the values before and after, when the edit is one value ("" otherwise)

    bool empty() const { return what.empty(); }
    // "WHAT FROM -> TO", or "WHAT" when there are no values.
    std::string label() const { return from.empty() && to.empty() ? what : what + " " + from + " -> " + to; }
    void clear() { what.clear(), from.clear(), to.clear(); }
};

}  // namespace m3055::explore
