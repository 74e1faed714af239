// Text cut at a window's edge, found by ImGui itself. A
// window's content (labels, text, widgets: ImGui's DC.CursorMaxPos) that
// reaches past the edge it is clipped at is text the user cannot read. With
// M3055_CHECK_CLIPPING set in the environment (the tests set it), the
// explorer prints each window clipped in two frames in a row (the side panel
// widens after one) once to stderr:
//   clipped: WINDOW: content N px past its edge at window width W
// Windows that size themselves (tooltips, popups, auto-resizing) or scroll
// sideways on purpose are not checked. The docked views that must show whole
// (kWholeViews: their plots are sized to the room) are also checked below:
//   clipped: WINDOW: content N px below its edge at window height H
#pragma once

#include <string>
#include <vector>

namespace m3055::explore {

struct ClippedWindow {
    std::string name;
    float overflow = 0.0f;  // ImGui units past the clipping edge
    float width = 0.0f;     // the window's width (height, for `below`)
    bool below = false;     // past its bottom edge, not its right one
};

// The windows whose content must fit their height (no scrolling to see a plot's axis).
inline const char* const kWholeViews[] = {"BRDF views", "Spectra"};

// This frame's windows with content past their right edge (after ImGui::Render).
std::vector<ClippedWindow> clipped_windows();

// Prints the clipped windows not printed before, when M3055_CHECK_CLIPPING is set.
void report_clipping();

}  // namespace m3055::explore
