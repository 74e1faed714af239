// The explorer's non-finite pixels (explore/nonfinite_view.h): which display
// pixels are NaN or infinite, the warning line over the display, and the
// probe's mark on such a pixel. No window, no GL: raw images made here.
#include "analysis/pixel_probe.h"
#include "explore/nonfinite_view.h"

#include <gtest/gtest.h>

#include <limits>

namespace m3055::explore {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// A w x h raw image (rows bottom to top, as Renderer::read_raw) of 0.5 grey.
RgbFloatImage grey_raw(int w, int h) {
    RgbFloatImage raw;
    raw.width = w;
    raw.height = h;
    raw.pixels.assign(std::size_t(w) * std::size_t(h) * 3, 0.5f);
    return raw;
}

void set_raw(RgbFloatImage& raw, int x, int raw_row, int channel, float value) {
    raw.pixels[(std::size_t(raw_row) * std::size_t(raw.width) + std::size_t(x)) * 3 + std::size_t(channel)] = value;
}

TEST(ExploreNonFinite, FiniteRenderHasNoWarningAndNoMarks) {
    const NonFiniteView view = nonfinite_view(grey_raw(8, 4));
    EXPECT_EQ(view.counts.pixels, 0u);
    EXPECT_TRUE(view.marked.empty());
    EXPECT_FALSE(view.is_marked(0, 0));
    EXPECT_EQ(nonfinite_warning(view.counts), "");
}

TEST(ExploreNonFinite, MarksThePixelsInDisplayRowsAndCountsNaNAndInf) {
    RgbFloatImage raw = grey_raw(8, 4);
    set_raw(raw, 1, 0, 2, kNaN);   // the bottom raw row: display row 3
    set_raw(raw, 6, 3, 0, kInf);   // the top raw row: display row 0
    set_raw(raw, 7, 3, 1, -kInf);
    const NonFiniteView view = nonfinite_view(raw);
    EXPECT_EQ(view.counts.pixels, 3u);
    EXPECT_EQ(view.counts.nan, 1u);
    EXPECT_EQ(view.counts.inf, 2u);
    EXPECT_TRUE(view.is_marked(1, 3));
    EXPECT_TRUE(view.is_marked(6, 0));
    EXPECT_TRUE(view.is_marked(7, 0));
    int marked = 0;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) marked += view.is_marked(x, y) ? 1 : 0;
    EXPECT_EQ(marked, 3);
    EXPECT_FALSE(view.is_marked(1, 0)) << "rows are the display's, top to bottom";
    EXPECT_FALSE(view.is_marked(-1, 0));
    EXPECT_FALSE(view.is_marked(8, 0));
    EXPECT_EQ(nonfinite_warning(view.counts),
              "Warning: 3 pixels are not finite (1 NaN, 2 infinite) (the material's values there are not numbers; "
              "the display shows some level for them). Hover to probe them.");
}

TEST(ExploreNonFinite, WarningNamesNaNAlone) {
    RgbFloatImage raw = grey_raw(4, 2);
    for (int x = 0; x < 4; ++x) set_raw(raw, x, 1, 0, kNaN);
    EXPECT_EQ(nonfinite_warning(nonfinite_view(raw).counts).rfind("Warning: 4 pixels are NaN (", 0), 0u);
    RgbFloatImage one = grey_raw(4, 2);
    set_raw(one, 0, 0, 1, kInf);
    EXPECT_EQ(nonfinite_warning(nonfinite_view(one).counts).rfind("Warning: 1 pixel is infinite (", 0), 0u);
}

TEST(ExploreNonFinite, TheProbeMarksANonFinitePixelOnly) {
    Scene scene;
    scene.display.width = 4;
    scene.display.height = 2;
    RgbFloatImage raw = grey_raw(4, 2);
    set_raw(raw, 2, 1, 0, kNaN);  // display pixel (2, 0)
    set_raw(raw, 3, 0, 1, kInf);  // display pixel (3, 1)
    Rgb8Image display;
    display.width = 4;
    display.height = 2;
    display.pixels.assign(4 * 2 * 3, 128);
    const ScenePicker picker(scene);
    const PixelProbe nan = probe_pixel(scene, picker, raw, display, 2, 0, -1);
    EXPECT_FALSE(nan.finite());
    const std::string text = nan.text();
    EXPECT_EQ(text.substr(text.rfind('\n') + 1), "NOT FINITE: NaN (the display's level here means nothing)") << text;
    const std::string inf = probe_pixel(scene, picker, raw, display, 3, 1, -1).text();
    EXPECT_EQ(inf.substr(inf.rfind('\n') + 1), "NOT FINITE: infinite (the display's level here means nothing)") << inf;
    const PixelProbe fine = probe_pixel(scene, picker, raw, display, 2, 1, -1);
    EXPECT_TRUE(fine.finite());
    EXPECT_EQ(fine.text().find("NOT FINITE"), std::string::npos);
}

}  // namespace
}  // namespace m3055::explore
