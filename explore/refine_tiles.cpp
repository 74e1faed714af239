#include "explore/refine_tiles.h"

#include <algorithm>

namespace m3055::explore {

void RefineTiles::start(int width, int height, bool sharpen_first) {
    width_ = width;
    height_ = height;
    band_top_ = height;
    band_bottom_ = height;
    band_x_ = 0;
    tiles_drawn_ = 0;
    last_pixels_ = 0;
    sharpening_ = sharpen_first;
}

double RefineTiles::progress() const {
    const double total = double(width_) * height_;
    if (total <= 0.0) return 1.0;
    return (double(height_ - band_top_) * width_ + double(band_x_) * (band_top_ - band_bottom_)) / total;
}

DisplayRegion RefineTiles::next(double budget_ms) const {
    // The pixels this tile may take: the first few, then the budget at the last
    // tile's cost, at most twice the last tile and kMaxTilePixels.
    double pixels = kFirstTilePixels;
    if (tiles_drawn_ > 0) {
        if (ms_per_pixel_ > 0.0) pixels = budget_ms / ms_per_pixel_;
        pixels = std::min({pixels, 2.0 * last_pixels_, double(kMaxTilePixels)});
    }
    int bottom = band_bottom_;
    if (band_x_ == 0) {  // a new band: as many whole rows as the pixels allow across the width, on the grid
        const int rows = std::max(kAlign, static_cast<int>(pixels / width_) / kAlign * kAlign);
        bottom = std::max(0, (band_top_ - rows) / kAlign * kAlign);
    }
    const int rows = band_top_ - bottom;
    int columns = std::max(kAlign, static_cast<int>(pixels / rows) / kAlign * kAlign);
    columns = std::min(columns, width_ - band_x_);
    if (width_ - band_x_ - columns < kAlign) columns = width_ - band_x_;  // no sliver left for a tile of its own
    return {band_x_, bottom, band_x_ + columns, band_top_};
}

void RefineTiles::drawn(const DisplayRegion& tile, double ms) {
    const int pixels = (tile.x1 - tile.x0) * (tile.y1 - tile.y0);
    if (tiles_drawn_ > 0 && pixels > 0) ms_per_pixel_ = ms / pixels;
    last_pixels_ = pixels;
    ++tiles_drawn_;
    band_bottom_ = tile.y0;
    band_x_ = tile.x1;
    if (band_x_ >= width_) {
        band_x_ = 0;
        band_top_ = band_bottom_;
    }
    if (band_top_ <= 0 && sharpening_) {  // the render's pass next, from the top
        sharpening_ = false;
        band_top_ = band_bottom_ = height_;
        band_x_ = 0;
        last_pixels_ = kFirstTilePixels / 2;  // its first tile small again: the render's samples cost more
    }
}

}  // namespace m3055::explore
