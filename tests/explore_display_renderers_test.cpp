// The explorer's preview rule without a GPU: which scenes are previewed, and
// how much smaller a preview is drawn for a frame to fit kPreviewBudgetMs.
#include "explore/display_renderers.h"

#include "scene/presets.h"

#include <gtest/gtest.h>

namespace m3055::explore {
namespace {

TEST(PreviewScale, DrawsAtTheDisplaysSizeUntilAFrameIsTooSlow) {
    PreviewScale scale;
    EXPECT_EQ(scale.divisor(), 1);
    scale.note(20.0, 1);
    EXPECT_EQ(scale.divisor(), 1);
}

TEST(PreviewScale, TakesTheSmallestDivisorWhoseFrameFitsTheBudget) {
    PreviewScale scale;
    scale.note(4.0 * kPreviewBudgetMs, 1);  // a quarter of the pixels fits
    EXPECT_EQ(scale.divisor(), 2);
    scale.note(kPreviewBudgetMs, 2);  // the same cost per pixel, measured at the half size
    EXPECT_EQ(scale.divisor(), 2);
    scale.note(9.5 * kPreviewBudgetMs, 1);
    EXPECT_EQ(scale.divisor(), 4);
    scale.note(1e6, 1);
    EXPECT_EQ(scale.divisor(), kMaxPreviewDivisor);
}

TEST(PreviewDiffers, OnlyWithAnAreaOrSkyLightThatReachesTheShader) {
    Scene scene = default_scene();
    EXPECT_FALSE(preview_differs(scene));
    for (LightType type : {LightType::rect, LightType::disk, LightType::sky}) {
        Scene area = scene;
        area.lights[0].type = type;
        EXPECT_TRUE(preview_differs(area));
        area.lights[0].enabled = false;
        EXPECT_FALSE(preview_differs(area));
    }
}

}  // namespace
}  // namespace m3055::explore
