// Where the explorer's refine of an area-light preview draws next
// (app/explore_ui/display_panes.h): the display in tiles, top down, each a
// part of a band of rows, each sized to take about kRefineBandMs from what the
// last one cost, so input waits for one tile at most. No GL: the panes draw
// each tile with Renderer::render_region. A preview drawn smaller than the
// display is first sharpened: a pass of the preview's own sampling at the
// display's size (about 1 s for the softbox at 512 x 320 on llvmpipe), then
// the pass of the render's (12 s and more), so that the display is whole and
// nearly right soon after input stops.
//
// Why tiles and not whole rows: a row of the sky fill at 512 px costs 0.3 to 1 s
// on llvmpipe (docs/lights.md), and a band thinner than 4 rows costs as much as
// 4 rows (llvmpipe shades blocks of 4 x 4 pixels, the scissored ones too), so
// bands are 4 rows (or a multiple) on a 4-row grid, and split in columns on a
// 4-column grid.
#pragma once

#include "frame/renderer.h"

namespace m3055::explore {

class RefineTiles {
public:
    static constexpr int kAlign = 4;             // llvmpipe's block side
    static constexpr int kFirstTilePixels = 256;  // the first may build a program too: kept small
    // However cheap the last tile was: costs vary across a display (the sky's
    // background rows cost nothing, the subject's up to 1 ms a pixel on llvmpipe),
    // and a cheap tile says nothing of the next.
    static constexpr int kMaxTilePixels = 2048;

    // A new refine of a width x height display, from its top row; `sharpen_first`:
    // a pass of the preview's sampling before the render's.
    void start(int width, int height, bool sharpen_first = false);
    bool done() const { return band_top_ <= 0 && !sharpening_; }
    // The pass under way draws the preview's sampling (kFastSampling), not the render's.
    bool sharpening() const { return sharpening_; }
    // The share of the display the pass under way has drawn (0 ... 1).
    double progress() const;
    bool started() const { return tiles_drawn_ > 0; }

    // The next tile to draw, for a tile to take about `budget_ms`.
    DisplayRegion next(double budget_ms) const;
    // `tile` (what next gave) drawn in `ms`.
    void drawn(const DisplayRegion& tile, double ms);

private:
    int width_ = 0, height_ = 0;
    int band_top_ = 0, band_bottom_ = 0;  // the band being refined: rows [band_bottom_, band_top_)
    int band_x_ = 0;                      // its columns refined so far: [0, band_x_)
    int tiles_drawn_ = 0;
    bool sharpening_ = false;
    int last_pixels_ = 0;        // the last tile's size
    double ms_per_pixel_ = 0.0;  // the last tile's cost (not the first's: it may include a compile)
};

}  // namespace m3055::explore
