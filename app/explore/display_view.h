// Where things go in the window, and the emulated display drawn into it:
// the display texture(s) magnified by whole pixels, nearest-neighbour.
#pragma once

#include "gl/gl_api.h"
#include "image/image.h"

#include <string>
#include <vector>

namespace m3055::explore {

struct Rect {
    float x = 0, y = 0, w = 0, h = 0;
};

// The side panel, the bottom strip and the display's area (ImGui units).
struct Layout {
    Rect side, bottom, display;
};

inline constexpr float kCompareGap = 8.0f;  // between the A and B displays

Layout layout_for(float width, float height, bool panels);

// One picture of the display area: a texture of the display's size (row 0
// at the bottom) and its label (above it; under it in the second row).
struct Pane {
    unsigned texture = 0;
    std::string label;
};

// Draws the panes (A; A and B in compare; A, B and |A - B| with the
// difference pane; then the assignment's reference with --assignment) centred
// in `area`, all at the largest whole magnification that fits (shrunk, no
// longer whole pixels, when even 1:1 does not fit): side by side, or from
// three panes on in two columns when that fits a larger magnification. Returns that scale (0: shrunk). `shown_a`, when given,
// receives where A is drawn (ImGui units).
int draw_display(const std::vector<Pane>& panes, int width, int height, const Rect& area, float fb_scale,
                 Rect* shown_a = nullptr);

// Puts `image` (rows top to bottom, as PNGs) into `texture` (made when 0) the
// way the renderer's display textures hold theirs: rows bottom to top,
// nearest-neighbour, so draw_display shows every pane alike, dot for dot.
void upload_pane_texture(const GlApi& gl, unsigned& texture, const Rgb8Image& image);

// The whole window as the user sees it (the back buffer, after ImGui has drawn).
Rgb8Image read_window(const GlApi& gl, int width, int height);

}  // namespace m3055::explore
