// The emulated display drawn into the window: the display texture(s)
// magnified by whole pixels, nearest-neighbour, where explore/layout.h puts them.
#pragma once

#include "explore/layout.h"
#include "gl/gl_api.h"
#include "gl/gl_object.h"
#include "image/image.h"

#include <string>
#include <vector>

namespace m3055::explore {

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

// The selected object's outline over a display drawn at `shown`: the pixels
// around it (its own pixels stay as rendered); `ids` the object per display
// pixel (explore/readouts.h object_ids).
void draw_selection_outline(const std::vector<int>& ids, int selected, int width, int height, const Rect& shown);

// Puts `image` (rows top to bottom, as PNGs) into `texture` (made when empty) the
// way the renderer's display textures hold theirs: rows bottom to top,
// nearest-neighbour, so draw_display shows every pane alike, dot for dot.
void upload_pane_texture(const GlApi& gl, GlTexture& texture, const Rgb8Image& image);

// A pane's texture of its own (the assignment's reference), deleted with it.
class PaneTexture {
public:
    PaneTexture(const GlApi& gl, const Rgb8Image& image) { upload_pane_texture(gl, texture_, image); }
    unsigned texture() const { return texture_.id(); }

private:
    GlTexture texture_;
};

// The whole window as the user sees it (the back buffer, after ImGui has drawn).
Rgb8Image read_window(const GlApi& gl, int width, int height);

}  // namespace m3055::explore
