// The A/B split's read-outs (grading/ab_compare.h) and the scanline
// profile (analysis/pixel_probe.h's row_profile) on two headless renders whose
// scenes differ in one parameter: the level-difference count, the scaled
// difference image and the row profile against direct counts on the PNGs. The explorer's own panes against headless renders are in
// explorer_test.cpp (CompareReadoutsEqualTheHeadlessRenders).
#include "analysis/pixel_probe.h"
#include "grading/ab_compare.h"
#include "grading/level_compare.h"
#include "image/image.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

namespace m3055 {
namespace {

using namespace grading;
using test::TempDir;

// fig10 (A), and fig10 with the middle sphere's second lobe sharper (B).
struct TwoRenders {
    TempDir dir;
    Rgb8Image a, b;
    TwoRenders() {
        const std::string scene = test::source_path("scenes/fig10.json");
        const auto ra = test::run_m3055({"render", "--scene", scene, "--out", dir.file("a.png")});
        const auto rb = test::run_m3055({"render", "--scene", scene, "--set", "objects[1].material.lobes[1].m=0.25",
                                         "--out", dir.file("b.png")});
        EXPECT_EQ(ra.exit_code, 0) << ra.err;
        EXPECT_EQ(rb.exit_code, 0) << rb.err;
        a = read_png(dir.file("a.png"));
        b = read_png(dir.file("b.png"));
    }
};

TEST(AbCompare, LevelDifferenceCountsPixelsWithAnyChannelOnAnotherLevel) {
    const TwoRenders r;
    ASSERT_EQ(r.a.pixels.size(), r.b.pixels.size());
    // Each level has one PNG value (docs/spec.md#2-display): another byte is another level.
    std::uint64_t direct = 0;
    for (std::size_t p = 0; p < r.a.pixels.size(); p += 3)
        direct += !std::equal(&r.a.pixels[p], &r.a.pixels[p] + 3, &r.b.pixels[p]);
    const LevelDifference d = level_difference(r.a, r.b, 5);
    EXPECT_EQ(d.pixels, std::uint64_t(r.a.width) * r.a.height);
    EXPECT_EQ(d.differing, direct);
    EXPECT_GT(d.differing, 0u) << "B's sharper lobe changes the highlight";
    EXPECT_LT(d.differing, d.pixels / 2) << "only the middle sphere changes";
    EXPECT_DOUBLE_EQ(d.share(), double(direct) / double(d.pixels));
    EXPECT_EQ(level_difference(r.a, r.a, 5).differing, 0u);
}

TEST(AbCompare, ScaledDifferenceIsAbsoluteDifferenceTimesScaleClamped) {
    const TwoRenders r;
    for (int scale : {1, 4, auto_difference_scale(r.a, r.b)}) {
        const Rgb8Image diff = scaled_difference(r.a, r.b, scale);
        ASSERT_EQ(diff.width, r.a.width);
        ASSERT_EQ(diff.height, r.a.height);
        for (std::size_t i = 0; i < diff.pixels.size(); ++i) {
            const int expected = std::min(255, std::abs(int(r.a.pixels[i]) - int(r.b.pixels[i])) * scale);
            ASSERT_EQ(int(diff.pixels[i]), expected) << "byte " << i << ", scale " << scale;
        }
    }
    const int automatic = auto_difference_scale(r.a, r.b);
    int largest = 0;
    for (std::size_t i = 0; i < r.a.pixels.size(); ++i)
        largest = std::max(largest, std::abs(int(r.a.pixels[i]) - int(r.b.pixels[i])));
    ASSERT_GT(largest, 0);
    EXPECT_LE(largest * automatic, 255);
    EXPECT_GT(largest * (automatic + 1), 255) << "the largest whole scale";
    EXPECT_EQ(auto_difference_scale(r.a, r.a), 1);
}

TEST(AbCompare, RowProfileIsTheRowsLevels) {
    const TwoRenders r;
    const int row = r.a.height / 2, top = 31;
    const RowProfile profile = row_profile(r.a, 5, row);
    EXPECT_EQ(profile.row, row);
    for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(profile.levels[c].size(), std::size_t(r.a.width));
        for (int x = 0; x < r.a.width; ++x) {
            const int png = r.a.pixels[(std::size_t(row) * r.a.width + x) * 3 + c];
            EXPECT_EQ(png, (profile.levels[c][x] * 255 + top / 2) / top) << x;  // docs/spec.md#2-display
        }
    }
    EXPECT_THROW(row_profile(r.a, 5, r.a.height), std::out_of_range);
    EXPECT_THROW(row_profile(r.a, 5, -1), std::out_of_range);
}

TEST(AbCompare, DifferentSizesAreRefused) {
    Rgb8Image a{2, 1, std::vector<std::uint8_t>(6, 0)}, b{1, 2, std::vector<std::uint8_t>(6, 0)};
    EXPECT_THROW(scaled_difference(a, b, 1), grading::CompareError);
    EXPECT_THROW(level_difference(a, b, 5), grading::CompareError);
}

}  // namespace
}  // namespace m3055
