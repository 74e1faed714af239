// Where things go in the explorer's window, as arithmetic: the side panel,
// the bottom strip and the display's area, the whole-pixel magnification the
// display panes fit at, and the display pixel under a window point. No ImGui
// here (explore_ui/display_view.h draws what this decides), so it is tested
// without a window.
#pragma once

#include "scene/scene.h"

#include <optional>
#include <utility>

namespace m3055::explore {

struct Rect {
    float x = 0, y = 0, w = 0, h = 0;
};

// The side panel, the bottom strip and the display's area (ImGui units).
// plots_beside: the strip (polar plot, profile, statistics) is a column right
// of the display's area, which then has the window's whole height.
// plots_in_cell: three panes in two columns (A, B over |A - B|; practice:
// your scene, the reference over the difference) fill the display's area and
// the plots take the free cell beside the third pane; the side panel is
// narrowed to what is left of the window.
// plots_under_side: the panes one whole magnification larger than beside the
// usual panel (one pane at 3x at 1920 x 1080) at the right; the side panel
// (its narrow form) over the polar plot (`bottom`) in the column left of
// them; the scanline profile (`profile`) and the statistics (`stats`) in the
// band under the panes, a wide low room that suits them, so the controls
// get the column's height (stats.w == 0: the band is too low, both stay
// under the polar plot in the column).
struct Layout {
    Rect side, bottom, display;
    Rect stats;    // the statistics apart from the plots (plots_under_side only)
    Rect profile;  // the scanline profile apart from the polar plot (plots_under_side only; w == 0: under it)
    bool plots_beside = false;
    bool plots_in_cell = false;
    bool plots_under_side = false;
};

inline constexpr float kCompareGap = 8.0f;  // between the A and B displays
// The side panel's width: at least kSideWidth, wider when its content needs
// it (side_width; the panel's labels and text are never cut),
// but never so wide that one pane no longer fits at 1:1 beside it.
inline constexpr float kSideWidth = 440.0f;

Layout layout_for(float width, float height, bool panels, float side_width = kSideWidth);
// The layout that shows `panes` panes of w x h dots at a whole magnification
// of at least 1 with the panels shown, when one does: the plots under the
// display (layout_for) when the panes fit there; else the panes stacked at
// the window's full height and the plots in a column beside them (A over B
// at 1280 x 720; practice: your scene over the reference); for three panes,
// two columns with the plots in the fourth cell and a narrower side panel
// (at least kMinNarrowSideWidth). Never a fraction
// when a layout avoids it; layout_for's when none does (the statistics say
// "shrunk"; F1 hides the panels). Where one column at the left for the side
// panel over the plots (at least kMinPlotsBesideWidth wide) lets the panes
// show at a larger whole magnification than all of these, that column
// (plots_under_side: one pane at 3x instead of 2x at 1920 x 1080).
Layout layout_for_panes(float width, float height, bool panels, int panes, int w, int h, float fb_scale,
                        float label_h, float side_width = kSideWidth);
inline constexpr float kMinPlotsBesideWidth = 300.0f;  // the narrowest column the plots are useful in
inline constexpr float kMinNarrowSideWidth = 236.0f;   // the narrowest side panel whose labels still fit
// plots_under_side: the plots' part of the column (polar plot, profile; the
// statistics too when the band under the panes is lower than kMinStatsHeight).
inline constexpr float kPlotsUnderSideHeight = 430.0f;
// ... and the polar plot's alone, where the profile is in the band.
inline constexpr float kPolarUnderSideHeight = 300.0f;
inline constexpr float kMinStatsHeight = 100.0f;  // five lines: timings, scale, levels used, a message

// plots_under_side with the plots folded to their title bar (title_h high):
// the side panel takes the rest of the column; its controls stay where they were.
void fold_plots(Layout& l, float title_h);

// The largest whole-pixel magnification of a w x h image that fits
// area_w x area_h (framebuffer pixels); 0 when even 1:1 does not fit.
int whole_pixel_scale(int w, int h, float area_w, float area_h);

// Panes in `columns` columns (rows as needed) and the magnification they fit at.
struct Grid {
    int columns = 1, rows = 1;
    int scale = 0;      // whole pixels; 0: shrunk
    float shown = 0.0f;  // framebuffer pixels per dot
    bool label_right = false;  // the second row's one label in the free cell to its right
    float row_label_h = 0.0f;  // room above each row after the first for its labels
};

// n panes of w x h dots in `columns` columns within `area` (ImGui units,
// `fb_scale` framebuffer pixels each), with label_h of room for a row of labels.
Grid fit_grid(int n, int columns, int w, int h, const Rect& area, float fb_scale, float label_h);
// One row, or (two panes or more) one column, or (three panes or more) two
// columns, whichever magnifies more.
Grid best_grid(int n, int w, int h, const Rect& area, float fb_scale, float label_h);

// The room `n` panes take in grid `g` (ImGui units): what display_view.cpp
// draws, their labels included (one row: the labels' line above it).
struct Extent {
    float w = 0, h = 0;
};
Extent grid_extent(const Grid& g, int n, int w, int h, float fb_scale, float label_h);

// The display pixel (x, y; y = 0 the top row) under window point (mx, my)
// when the display is drawn at `shown` (ImGui units); none outside it.
std::optional<std::pair<int, int>> pixel_at(const Display& display, const Rect& shown, float mx, float my);

}  // namespace m3055::explore
