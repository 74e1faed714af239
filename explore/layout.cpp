// The window's layout and the panes' whole-pixel magnification: arithmetic only.
#include "explore/layout.h"

#include <algorithm>
#include <cmath>

namespace m3055::explore {

namespace {
constexpr float kBottomHeight = 270.0f;
}  // namespace

int whole_pixel_scale(int w, int h, float area_w, float area_h) {
    return static_cast<int>(std::min(std::floor(area_w / w), std::floor(area_h / h)));
}

Layout layout_for(float width, float height, bool panels, float side_width) {
    Layout l;
    if (!panels) {
        l.display = {0, 0, width, height};
        return l;
    }
    l.side = {0, 0, std::min(side_width, width), height};
    const float right = std::max(0.0f, width - l.side.w);
    l.bottom = {l.side.w, std::max(0.0f, height - kBottomHeight), right, std::min(kBottomHeight, height)};
    l.display = {l.side.w, 0, right, l.bottom.y};
    return l;
}

namespace {

// layout_for_panes without the column of plots_under_side.
Layout usual_layout(float width, float height, bool panels, int panes, int w, int h, float fb_scale,
                    float label_h, float side_width) {
    if (w > 0 && fb_scale > 0.0f)  // one pane at 1:1 beside the panel, whatever its content asks
        side_width = std::max(kSideWidth, std::min(side_width, width - float(w) / fb_scale - 3.0f * kCompareGap));
    const Layout under = layout_for(width, height, panels, side_width);
    if (!panels || panes < 1 || w <= 0 || h <= 0 || fb_scale <= 0.0f) return under;
    if (best_grid(panes, w, h, under.display, fb_scale, label_h).scale >= 1) return under;
    // The panes in one column (or two) at the whole height; the plots beside them.
    for (const int columns : {1, 2}) {
        if (columns > panes) break;
        Layout beside;
        beside.plots_beside = true;
        beside.side = under.side;
        const float right = std::max(0.0f, width - under.side.w);
        const float column_w = float(columns) * float(w) / fb_scale + kCompareGap * float(columns + 1);
        beside.display = {under.side.w, 0, std::min(column_w, right), height};
        beside.bottom = {under.side.w + beside.display.w, 0, right - beside.display.w, height};
        if (beside.bottom.w >= kMinPlotsBesideWidth &&
            fit_grid(panes, columns, w, h, beside.display, fb_scale, label_h).scale >= 1)
            return beside;
    }
    // Three panes: two columns at 1:1 (or more) as high as the window
    // allows, the side panel narrowed to the rest, the plots in the free cell.
    if (panes == 3) {
        for (int scale = 8; scale >= 1; --scale) {
            const float iw = float(w * scale) / fb_scale, ih = float(h * scale) / fb_scale;
            Layout cell;
            cell.plots_in_cell = true;
            // 2 px round the panes for their frames; labels above the first row.
            cell.display = {0, 0, 2.0f * iw + kCompareGap + 4.0f, label_h + 2.0f * ih + kCompareGap + 4.0f};
            cell.side = {0, 0, std::min(side_width, width - cell.display.w), height};
            if (cell.side.w < kMinNarrowSideWidth || cell.display.h > height) continue;
            cell.display.x = cell.side.w + (width - cell.side.w - cell.display.w);  // flush right
            if (fit_grid(3, 2, w, h, cell.display, fb_scale, label_h).scale != scale) continue;
            // The free cell: right of the third pane, under its label line.
            const float cell_x = cell.display.x + 2.0f + iw + kCompareGap * 0.5f;
            const float cell_y = label_h + ih + kCompareGap + 2.0f + label_h * 1.5f;
            cell.bottom = {cell_x, cell_y, width - cell_x, height - cell_y};
            if (cell.bottom.w >= kMinPlotsBesideWidth && cell.bottom.h >= 200.0f) return cell;
        }
    }
    return under;
}

// The side panel over the plots in one column at the left, the panes at the
// right at the largest whole magnification the column's narrowest width
// leaves them, the statistics under the panes; plots_under_side false when
// no such layout fits.
Layout column_layout(float width, float height, int panes, int w, int h, float fb_scale, float label_h) {
    Layout l;
    const Rect widest{kMinPlotsBesideWidth, 0, width - kMinPlotsBesideWidth, height};
    if (widest.w <= 0.0f) return l;
    const Grid g = best_grid(panes, w, h, widest, fb_scale, label_h);
    if (g.scale < 1) return l;
    // The panes with half a gap round them (their frames); the column takes
    // the rest of the width, the statistics the rest of the height.
    const Extent e = grid_extent(g, panes, w, h, fb_scale, label_h);
    l.display = {0, 0, std::min(widest.w, e.w + kCompareGap), std::min(height, e.h + kCompareGap)};
    l.display.x = width - l.display.w;
    if (height - l.display.h < kMinStatsHeight) {
        l.display.h = height;  // the profile and the statistics stay in the column
    } else {  // the band: the profile at its left (as wide as the column), the statistics beside it
        const float band_y = l.display.h, band_h = height - l.display.h;
        l.profile = {l.display.x, band_y, std::min(l.display.x, l.display.w * 0.5f), band_h};
        l.stats = {l.profile.x + l.profile.w, band_y, l.display.w - l.profile.w, band_h};
    }
    if (best_grid(panes, w, h, l.display, fb_scale, label_h).scale != g.scale) return Layout{};
    const float column_w = l.display.x;
    const float plots_h = std::min(height * 0.5f, l.stats.w > 0.0f ? kPolarUnderSideHeight
                                                                   : kPlotsUnderSideHeight + 8.0f * label_h);
    l.side = {0, 0, column_w, height - plots_h};
    l.bottom = {0, l.side.h, column_w, plots_h};
    l.plots_under_side = column_w >= kMinNarrowSideWidth;
    return l;
}

}  // namespace

Layout layout_for_panes(float width, float height, bool panels, int panes, int w, int h, float fb_scale,
                        float label_h, float side_width) {
    const Layout usual = usual_layout(width, height, panels, panes, w, h, fb_scale, label_h, side_width);
    if (!panels || panes < 1 || w <= 0 || h <= 0 || fb_scale <= 0.0f) return usual;
    const Layout column = column_layout(width, height, panes, w, h, fb_scale, label_h);
    if (column.plots_under_side && best_grid(panes, w, h, column.display, fb_scale, label_h).scale >
                                       best_grid(panes, w, h, usual.display, fb_scale, label_h).scale)
        return column;
    return usual;
}

void fold_plots(Layout& l, float title_h) {
    if (!l.plots_under_side) return;
    const float bottom = l.bottom.y + l.bottom.h;
    l.bottom.h = std::min(title_h, l.bottom.h);
    l.bottom.y = bottom - l.bottom.h;
    l.side.h = l.bottom.y - l.side.y;
}

Extent grid_extent(const Grid& g, int n, int w, int h, float fb_scale, float label_h) {
    const float iw = float(w) * g.shown / fb_scale, ih = float(h) * g.shown / fb_scale;
    Extent e;
    e.w = iw * float(g.columns) + kCompareGap * float(g.columns - 1);
    // Two panes or more have a label each, above its row (display_view.cpp).
    const float first_label_h = n >= 2 ? label_h : 0.0f;
    e.h = first_label_h + ih * float(g.rows) + (kCompareGap + g.row_label_h) * float(g.rows - 1);
    return e;
}

// Labels sit above their row. Exceptions that keep a whole magnification
// where it matters: one row keeps its labels in the margin above, and a
// second row of one pane (A, B and |A - B|) has its label in the free cell to
// its right, so only the first row's labels need room.
Grid fit_grid(int n, int columns, int w, int h, const Rect& area, float fb_scale, float label_h) {
    Grid g;
    g.columns = columns;
    g.rows = (n + columns - 1) / columns;
    g.label_right = columns >= 2 && g.rows == 2 && n == columns + 1;
    const int label_rows = g.rows == 1 ? 0 : g.label_right ? 1 : g.rows;
    g.row_label_h = g.rows > 1 && !g.label_right ? label_h : 0.0f;
    const float room_h = area.h - label_h * float(label_rows) - kCompareGap * float(g.rows - 1);
    const float area_w = (area.w - kCompareGap * float(columns - 1)) * fb_scale / float(columns);
    const float area_h = room_h * fb_scale / float(g.rows);
    g.scale = whole_pixel_scale(w, h, area_w, area_h);
    // Too big even at 1:1: shrink to fit (no longer whole pixels; the panel says so).
    g.shown = g.scale >= 1 ? float(g.scale) : std::min(area_w / float(w), area_h / float(h));
    return g;
}

Grid best_grid(int n, int w, int h, const Rect& area, float fb_scale, float label_h) {
    Grid g = fit_grid(n, n, w, h, area, fb_scale, label_h);
    if (n >= 2) {  // stacked, one column
        const Grid column = fit_grid(n, 1, w, h, area, fb_scale, label_h);
        if (column.shown > g.shown) g = column;
    }
    if (n >= 3) {  // two columns (e.g. A and B, |A - B| under A) when that magnifies more
        const Grid two_rows = fit_grid(n, 2, w, h, area, fb_scale, label_h);
        if (two_rows.shown > g.shown) g = two_rows;
    }
    return g;
}

std::optional<std::pair<int, int>> pixel_at(const Display& display, const Rect& shown, float mx, float my) {
    if (shown.w <= 0 || shown.h <= 0) return std::nullopt;
    const int x = static_cast<int>(std::floor((mx - shown.x) / shown.w * display.width));
    const int y = static_cast<int>(std::floor((my - shown.y) / shown.h * display.height));
    if (x < 0 || y < 0 || x >= display.width || y >= display.height) return std::nullopt;
    return std::make_pair(x, y);
}

}  // namespace m3055::explore
