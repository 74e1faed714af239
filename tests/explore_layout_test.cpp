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

// At 1280 x 720 with the panels shown, A and B (or your
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

// Three panes (A, B, |A - B|; practice: your scene, the
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

// At 1920 x 1080 one pane shows at 3x (2x beside the usual 440-px panel):
// the side panel in its narrow form over the polar plot in one column at the
// left, the pane at the right, the scanline profile and the statistics in
// the band under it (a wide low room that suits them: the controls get the
// column's height but for the polar plot).
TEST(ExploreLayout, At1920x1080OnePaneShowsAt3xWithTheSidePanelOverThePlots) {
    const float label_h = 21.0f;
    EXPECT_EQ(best_grid(1, 512, 320, layout_for(1920, 1080, true).display, 1.0f, label_h).scale, 2)
        << "beside the usual panel";
    const Layout l = layout_for_panes(1920, 1080, true, 1, 512, 320, 1.0f, label_h);
    ASSERT_TRUE(l.plots_under_side);
    EXPECT_EQ(best_grid(1, 512, 320, l.display, 1.0f, label_h).scale, 3);
    // The column: the side panel (narrow form) over the plots, the window's height.
    EXPECT_FLOAT_EQ(l.side.x, 0.0f);
    EXPECT_FLOAT_EQ(l.side.y, 0.0f);
    EXPECT_GE(l.side.w, kMinNarrowSideWidth);
    EXPECT_LT(l.side.w, kSideWidth) << "the narrow form";
    EXPECT_FLOAT_EQ(l.bottom.x, 0.0f);
    EXPECT_FLOAT_EQ(l.bottom.w, l.side.w);
    EXPECT_FLOAT_EQ(l.bottom.y, l.side.h);
    EXPECT_FLOAT_EQ(l.bottom.y + l.bottom.h, 1080.0f);
    EXPECT_GE(l.bottom.h, kPolarUnderSideHeight);
    EXPECT_GE(l.side.h, 1080.0f - kPolarUnderSideHeight) << "the controls keep the column but for the polar plot";
    // The pane right of the column, the statistics under it, all in the window.
    EXPECT_FLOAT_EQ(l.display.x, l.side.w);
    EXPECT_FLOAT_EQ(l.display.x + l.display.w, 1920.0f);
    EXPECT_GE(l.display.w, 3.0f * 512.0f);
    EXPECT_GE(l.display.h, 3.0f * 320.0f);
    // The band: the profile at its left, the statistics beside it, together its whole width.
    EXPECT_FLOAT_EQ(l.profile.x, l.display.x);
    EXPECT_FLOAT_EQ(l.profile.y, l.display.h);
    EXPECT_GE(l.profile.w, 300.0f) << "room for the 2^bits steps of a row";
    EXPECT_FLOAT_EQ(l.stats.x, l.profile.x + l.profile.w);
    EXPECT_FLOAT_EQ(l.stats.x + l.stats.w, l.display.x + l.display.w);
    EXPECT_FLOAT_EQ(l.stats.y, l.display.h);
    EXPECT_FLOAT_EQ(l.stats.y + l.stats.h, 1080.0f);
    EXPECT_FLOAT_EQ(l.profile.h, l.stats.h);
    EXPECT_GE(l.stats.h, kMinStatsHeight);
    // Panels hidden (F1): the whole window, as before.
    EXPECT_FALSE(layout_for_panes(1920, 1080, false, 1, 512, 320, 1.0f, label_h).plots_under_side);
}

// Too low a band under the 3x pane for the statistics: they stay in the
// column under the plots, and the pane has the window's height.
TEST(ExploreLayout, WithNoRoomUnderThePaneTheStatisticsStayInTheColumn) {
    const Layout l = layout_for_panes(1920, 1000, true, 1, 512, 320, 1.0f, 21.0f);
    ASSERT_TRUE(l.plots_under_side);
    EXPECT_EQ(best_grid(1, 512, 320, l.display, 1.0f, 21.0f).scale, 3);
    EXPECT_FLOAT_EQ(l.stats.w, 0.0f);
    EXPECT_FLOAT_EQ(l.profile.w, 0.0f) << "the profile too";
    EXPECT_FLOAT_EQ(l.display.h, 1000.0f);
    EXPECT_GT(l.bottom.h, kPlotsUnderSideHeight) << "room for the statistics under the plots";
    EXPECT_FLOAT_EQ(l.bottom.y + l.bottom.h, 1000.0f);
}

// The column is taken only where it magnifies more: 1280 x 720 (every pane
// count), 1500 x 940 (2x either way) and, at 1920 x 1080, A/B and practice
// (two or three panes: 1x either way) keep the layouts they had.
TEST(ExploreLayout, TheColumnOnlyWhereItMagnifiesMore) {
    const float label_h = 21.0f;
    for (int panes = 1; panes <= 3; ++panes) {
        EXPECT_FALSE(layout_for_panes(1280, 720, true, panes, 512, 320, 1.0f, label_h).plots_under_side) << panes;
        EXPECT_FALSE(layout_for_panes(1500, 940, true, panes, 512, 320, 1.0f, label_h).plots_under_side) << panes;
    }
    for (int panes = 2; panes <= 3; ++panes) {
        const Layout l = layout_for_panes(1920, 1080, true, panes, 512, 320, 1.0f, label_h);
        EXPECT_FALSE(l.plots_under_side) << panes;
        EXPECT_EQ(best_grid(panes, 512, 320, l.display, 1.0f, label_h).scale, 1) << panes;
        // Even the column at its narrowest would not show them larger.
        const Rect widest{kMinPlotsBesideWidth, 0, 1920 - kMinPlotsBesideWidth, 1080};
        EXPECT_EQ(best_grid(panes, 512, 320, widest, 1.0f, label_h).scale, 1) << panes;
    }
}

// The plots under the side panel folded to their title bar: the side panel
// takes the column; its top (and its controls) stay; nothing else moves.
TEST(ExploreLayout, FoldedPlotsGiveTheColumnToTheSidePanel) {
    const Layout open = layout_for_panes(1920, 1080, true, 1, 512, 320, 1.0f, 21.0f);
    Layout folded = open;
    fold_plots(folded, 21.0f);
    EXPECT_FLOAT_EQ(folded.side.y, open.side.y);
    EXPECT_FLOAT_EQ(folded.side.h, 1080.0f - 21.0f);
    EXPECT_FLOAT_EQ(folded.bottom.y, 1080.0f - 21.0f);
    EXPECT_FLOAT_EQ(folded.bottom.h, 21.0f);
    EXPECT_FLOAT_EQ(folded.bottom.w, open.bottom.w);
    EXPECT_FLOAT_EQ(folded.display.x, open.display.x);
    EXPECT_FLOAT_EQ(folded.display.h, open.display.h);
    // Other layouts have no plots under the side panel: unchanged.
    const Layout usual = layout_for_panes(1280, 720, true, 1, 512, 320, 1.0f, 21.0f);
    Layout same = usual;
    fold_plots(same, 21.0f);
    EXPECT_FLOAT_EQ(same.side.h, usual.side.h);
    EXPECT_FLOAT_EQ(same.bottom.h, usual.bottom.h);
}

TEST(ExploreLayout, GridExtentIsThePanesAndTheirLabels) {
    const Rect area{0, 0, 2000, 1000};
    const Grid one = best_grid(1, 512, 320, area, 1.0f, 21.0f);
    const Extent e1 = grid_extent(one, 1, 512, 320, 1.0f, 21.0f);
    EXPECT_FLOAT_EQ(e1.w, 3.0f * 512.0f);
    EXPECT_FLOAT_EQ(e1.h, 3.0f * 320.0f) << "one pane has no label";
    const Grid two = fit_grid(2, 2, 512, 320, area, 1.0f, 21.0f);
    const Extent e2 = grid_extent(two, 2, 512, 320, 1.0f, 21.0f);
    EXPECT_FLOAT_EQ(e2.w, 2.0f * 512.0f * float(two.scale) + kCompareGap);
    EXPECT_FLOAT_EQ(e2.h, 21.0f + 320.0f * float(two.scale)) << "the labels' line above the row";
    const Grid stacked = fit_grid(2, 1, 512, 320, area, 1.0f, 21.0f);
    EXPECT_FLOAT_EQ(grid_extent(stacked, 2, 512, 320, 1.0f, 21.0f).h,
                    21.0f + 2.0f * 320.0f * float(stacked.scale) + kCompareGap + 21.0f);
}

}  // namespace
}  // namespace m3055::explore
