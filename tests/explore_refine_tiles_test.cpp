// Where the refine of an area-light preview draws next (explore/refine_tiles.h):
// tiles cover the display once, top down, on llvmpipe's 4 x 4 grid, the
// first small, then sized to the budget from the last tile's cost and never
// more than twice the last; a preview drawn smaller: twice, the preview's
// sampling first.
#include "explore/refine_tiles.h"

#include <gtest/gtest.h>

#include <functional>
#include <vector>

namespace m3055::explore {
namespace {

// Draws every tile of a width x height display, `cost(tile)` ms each; the tiles in order.
std::vector<DisplayRegion> refine_all(int width, int height, const std::function<double(const DisplayRegion&)>& cost,
                                      bool sharpen_first = false, std::vector<bool>* sharpening = nullptr) {
    RefineTiles tiles;
    tiles.start(width, height, sharpen_first);
    std::vector<DisplayRegion> drawn;
    while (!tiles.done() && drawn.size() < 100000) {
        const DisplayRegion tile = tiles.next(60.0);
        drawn.push_back(tile);
        if (sharpening) sharpening->push_back(tiles.sharpening());
        tiles.drawn(tile, cost(tile));
    }
    return drawn;
}

double area(const DisplayRegion& t) { return double(t.x1 - t.x0) * (t.y1 - t.y0); }

TEST(RefineTiles, CoverTheDisplayOnceTopDownOnTheGrid) {
    for (const auto& [w, h] : {std::pair{512, 320}, std::pair{130, 83}, std::pair{3, 2}, std::pair{1, 1}}) {
        SCOPED_TRACE(std::to_string(w) + " x " + std::to_string(h));
        const auto drawn = refine_all(w, h, [](const DisplayRegion& t) { return 0.05 * area(t); });
        std::vector<int> covered(std::size_t(w) * h, 0);
        int last_top = h + 1;
        for (const DisplayRegion& t : drawn) {
            ASSERT_LT(t.x0, t.x1);
            ASSERT_LT(t.y0, t.y1);
            EXPECT_LE(t.y1, last_top);  // bands top down
            last_top = t.y1;
            if (t.y0 > 0) {
                EXPECT_EQ(t.y0 % RefineTiles::kAlign, 0);  // on the grid (the top band takes the rest)
            }
            if (t.x0 > 0) {
                EXPECT_EQ(t.x0 % RefineTiles::kAlign, 0);
            }
            for (int y = t.y0; y < t.y1; ++y)
                for (int x = t.x0; x < t.x1; ++x) ++covered[std::size_t(y) * w + x];
        }
        for (int c : covered) ASSERT_EQ(c, 1);
    }
}

TEST(RefineTiles, TilesFitTheBudgetAtTheLastTilesCost) {
    // 0.5 ms a pixel: a 60 ms tile is 120 pixels; the first is kFirstTilePixels.
    const auto drawn = refine_all(512, 320, [](const DisplayRegion& t) { return 0.5 * area(t); });
    EXPECT_LE(area(drawn[0]), RefineTiles::kFirstTilePixels);
    for (std::size_t i = 2; i + 1 < drawn.size(); ++i) {
        if (drawn[i].x1 == 512) continue;  // a band's last tile takes what is left
        EXPECT_LE(area(drawn[i]) * 0.5, 60.0 + 0.5 * 4 * 4) << i;
    }
}

TEST(RefineTiles, ACheapRegionDoesNotMakeTheNextTileLong) {
    // The top of the display (background) costs next to nothing, the rest 1 ms a pixel.
    const auto drawn = refine_all(512, 320, [](const DisplayRegion& t) { return t.y0 >= 200 ? 1e-4 * area(t) : area(t); });
    for (std::size_t i = 1; i < drawn.size(); ++i) {
        EXPECT_LE(area(drawn[i]), RefineTiles::kMaxTilePixels + 512.0 * RefineTiles::kAlign) << i;  // + a band's rest
        if (drawn[i].x1 != 512) {
            EXPECT_LE(area(drawn[i]), 2.0 * area(drawn[i - 1])) << i;
        }
    }
}

// A preview drawn smaller than the display: the preview's pass covers the display once,
// then the render's pass covers it once, from the top again, its first tile small.
TEST(RefineTiles, SharpenedFirstThenTheRendersPass) {
    std::vector<bool> sharpening;
    const auto drawn = refine_all(512, 320, [](const DisplayRegion& t) { return 0.01 * area(t); }, true, &sharpening);
    std::vector<int> covered(512 * 320, 0), covered_sharp(512 * 320, 0);
    std::size_t first_render_tile = drawn.size();
    for (std::size_t i = 0; i < drawn.size(); ++i) {
        if (!sharpening[i] && first_render_tile == drawn.size()) first_render_tile = i;
        if (i > first_render_tile) {
            EXPECT_FALSE(sharpening[i]) << i;  // one pass of each, in that order
        }
        for (int y = drawn[i].y0; y < drawn[i].y1; ++y)
            for (int x = drawn[i].x0; x < drawn[i].x1; ++x)
                ++(sharpening[i] ? covered_sharp : covered)[std::size_t(y) * 512 + x];
    }
    ASSERT_GT(first_render_tile, 0u);
    ASSERT_LT(first_render_tile, drawn.size());
    EXPECT_EQ(drawn[first_render_tile].y1, 320);
    EXPECT_LE(area(drawn[first_render_tile]), RefineTiles::kFirstTilePixels);
    for (std::size_t p = 0; p < covered.size(); ++p) {
        ASSERT_EQ(covered_sharp[p], 1) << p;
        ASSERT_EQ(covered[p], 1) << p;
    }
}

// The share drawn (the statistics' "N %"): 0 at a pass's start, growing tile by
// tile as the tiles' pixels, back to 0 for the render's pass.
TEST(RefineTiles, ProgressIsTheShareOfThePassDrawn) {
    RefineTiles tiles;
    tiles.start(130, 83, true);
    EXPECT_EQ(tiles.progress(), 0.0);
    double drawn_pixels = 0.0;
    bool sharpening = true;
    while (!tiles.done()) {
        const DisplayRegion tile = tiles.next(60.0);
        tiles.drawn(tile, 0.01 * area(tile));
        drawn_pixels += area(tile);
        if (sharpening && !tiles.sharpening()) {  // the preview's pass ended: the render's from 0
            EXPECT_EQ(drawn_pixels, 130.0 * 83.0);
            drawn_pixels = 0.0;
            sharpening = false;
        }
        EXPECT_DOUBLE_EQ(tiles.progress(), drawn_pixels / (130.0 * 83.0));
    }
    EXPECT_FALSE(sharpening);
    EXPECT_DOUBLE_EQ(tiles.progress(), 1.0);
}

TEST(RefineTiles, AStartBeginsAgainFromTheTop) {
    RefineTiles tiles;
    tiles.start(64, 40);
    tiles.drawn(tiles.next(60.0), 1.0);
    EXPECT_TRUE(tiles.started());
    tiles.start(64, 40);
    EXPECT_FALSE(tiles.started());
    EXPECT_EQ(tiles.next(60.0).y1, 40);
}

}  // namespace
}  // namespace m3055::explore
