// The explorer window's layout arithmetic (explore/layout.h), without a
// window: the display's area, whole-pixel magnifications and the display
// pixel under the mouse.
#include "explore/layout.h"

#include <gtest/gtest.h>

namespace m3055::explore {
namespace {

TEST(ExploreLayout, At1280x720TheM3055DisplayShowsWholeAt1To1BesideThePanels) {
    const Layout l = layout_for(1280, 720, true);
    EXPECT_EQ(l.side.w, 440);
    EXPECT_EQ(l.display.x, 440);
    EXPECT_GE(whole_pixel_scale(512, 320, l.display.w, l.display.h), 1);
    const Layout bare = layout_for(1280, 720, false);  // F1
    EXPECT_EQ(bare.display.w, 1280);
    EXPECT_EQ(bare.display.h, 720);
    EXPECT_EQ(whole_pixel_scale(512, 320, 1280, 720), 2);
}

TEST(ExploreLayout, WholePixelScaleIsZeroWhenEven1To1DoesNotFit) {
    EXPECT_EQ(whole_pixel_scale(512, 320, 511, 1000), 0);
    EXPECT_EQ(whole_pixel_scale(512, 320, 1536, 960), 3);
    EXPECT_EQ(whole_pixel_scale(512, 320, 1535, 960), 2);
}

TEST(ExploreLayout, ThreePanesTakeTwoColumnsWhenThatMagnifiesMore) {
    const Rect wide{0, 0, 3 * 512 + 2 * kCompareGap, 400};  // one row fits 1:1, two rows do not
    EXPECT_EQ(best_grid(3, 512, 320, wide, 1.0f, 20.0f).columns, 3);
    const Rect tall{0, 0, 2100, 1400};  // one row fits 1x, two columns of two rows fit 2x
    EXPECT_EQ(fit_grid(3, 3, 512, 320, tall, 1.0f, 20.0f).scale, 1);
    const Grid g = best_grid(3, 512, 320, tall, 1.0f, 20.0f);
    EXPECT_EQ(g.columns, 2);
    EXPECT_EQ(g.scale, 2);
    EXPECT_TRUE(g.label_right) << "the second row's one pane has its label beside it";
}

TEST(ExploreLayout, PixelUnderTheMouseFollowsTheShownMagnification) {
    Display d;
    d.width = 512;
    d.height = 320;
    const Rect shown{100, 50, 1024, 640};  // 2x
    EXPECT_EQ(pixel_at(d, shown, 100, 50), std::make_pair(0, 0));
    EXPECT_EQ(pixel_at(d, shown, 101.9f, 51.9f), std::make_pair(0, 0));
    EXPECT_EQ(pixel_at(d, shown, 102, 52), std::make_pair(1, 1));
    EXPECT_EQ(pixel_at(d, shown, 1123.9f, 689.9f), std::make_pair(511, 319));
    EXPECT_FALSE(pixel_at(d, shown, 1124, 100));
    EXPECT_FALSE(pixel_at(d, shown, 99.9f, 100));
    EXPECT_FALSE(pixel_at(d, Rect{}, 0, 0)) << "nothing drawn yet";
}

// Issue 20, item 5: at 1280 x 720 with the panels shown, A and B (or your
// scene and the practice reference) at a whole magnification: stacked at the
// window's height, the plots in a column beside them; never a fraction.
TEST(ExploreLayout, TwoPanesAt1280x720StackWithThePlotsBesideAtWholePixels) {
    const float label_h = 21.0f;
    const Layout one = layout_for_panes(1280, 720, true, 1, 512, 320, 1.0f, label_h);
    EXPECT_FALSE(one.plots_beside) << "one pane fits above the plots";
    EXPECT_GE(best_grid(1, 512, 320, one.display, 1.0f, label_h).scale, 1);
    const Layout two = layout_for_panes(1280, 720, true, 2, 512, 320, 1.0f, label_h);
    EXPECT_TRUE(two.plots_beside);
    const Grid g = best_grid(2, 512, 320, two.display, 1.0f, label_h);
    EXPECT_EQ(g.scale, 1);
    EXPECT_EQ(g.columns, 1) << "A over B";
    EXPECT_GE(two.bottom.w, kMinPlotsBesideWidth);
    EXPECT_FLOAT_EQ(two.bottom.x + two.bottom.w, 1280.0f);
    EXPECT_GE(two.bottom.x, two.display.x + 512.0f) << "the plots never over a pane";
    // At 1920 x 1080 the two fit side by side above the plots.
    const Layout big = layout_for_panes(1920, 1080, true, 2, 512, 320, 1.0f, label_h);
    EXPECT_FALSE(big.plots_beside);
    EXPECT_GE(best_grid(2, 512, 320, big.display, 1.0f, label_h).scale, 1);
    // With the panels hidden (F1) the display has the whole window.
    EXPECT_FALSE(layout_for_panes(1280, 720, false, 2, 512, 320, 1.0f, label_h).plots_beside);
}

// Issue 20, item 5: three panes (A, B, |A - B|; practice: your scene, the
// reference, the difference) at 1280 x 720 with the panels shown: two
// columns at 1:1, the plots in the free fourth cell, the side panel narrowed
// to the rest (never under kMinNarrowSideWidth); at 1920 x 1080 the usual
// layout already fits them at 1:1.
TEST(ExploreLayout, ThreePanesAt1280x720TakeTwoColumnsWithThePlotsInTheFourthCell) {
    const float label_h = 21.0f;
    const Layout l = layout_for_panes(1280, 720, true, 3, 512, 320, 1.0f, label_h);
    ASSERT_TRUE(l.plots_in_cell);
    const Grid g = best_grid(3, 512, 320, l.display, 1.0f, label_h);
    EXPECT_EQ(g.scale, 1);
    EXPECT_EQ(g.columns, 2);
    EXPECT_GE(l.side.w, kMinNarrowSideWidth);
    EXPECT_FLOAT_EQ(l.side.w + l.display.w, 1280.0f) << "the panes flush right of the side panel";
    EXPECT_LE(l.display.y + l.display.h, 720.0f);
    // The plots: right of the third pane (under A), below B, inside the window.
    EXPECT_GE(l.bottom.x, l.display.x + 2.0f + 512.0f);
    EXPECT_GE(l.bottom.y, label_h + 320.0f + kCompareGap);
    EXPECT_FLOAT_EQ(l.bottom.x + l.bottom.w, 1280.0f);
    EXPECT_FLOAT_EQ(l.bottom.y + l.bottom.h, 720.0f);
    EXPECT_GE(l.bottom.w, kMinPlotsBesideWidth);
    const Layout big = layout_for_panes(1920, 1080, true, 3, 512, 320, 1.0f, label_h);
    EXPECT_FALSE(big.plots_in_cell);
    EXPECT_FLOAT_EQ(big.side.w, 440.0f);
    EXPECT_GE(best_grid(3, 512, 320, big.display, 1.0f, label_h).scale, 1);
    // Too narrow for a usable side panel beside two columns: the usual layout (shrunk; F1 helps).
    EXPECT_FALSE(layout_for_panes(1200, 720, true, 3, 512, 320, 1.0f, label_h).plots_in_cell);
}

}  // namespace
}  // namespace m3055::explore
