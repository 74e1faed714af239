// The explorer's read-outs (renderer/analysis/pixel_probe.h) without a window:
// levels from PNG values, the level histogram, and the picker's rays. The
// probe against a headless render is in explorer_test.cpp (PixelProbeEqualsTheHeadlessRender).
#include "analysis/pixel_probe.h"
#include "scene/load.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace m3055 {
namespace {

TEST(PixelProbe, LevelOfPngInvertsTheSpecsEncoding) {
    for (int bits = 1; bits <= 8; ++bits) {
        const int top = (1 << bits) - 1;
        for (int level = 0; level <= top; ++level) {
            const int png = static_cast<int>(std::lround(level * 255.0 / top));  // docs/spec.md#2-display
            EXPECT_EQ(level_of_png(png, bits), level) << bits << " bits";
        }
    }
}

TEST(PixelProbe, HistogramCountsEveryPixelOncePerChannel) {
    Rgb8Image image;
    image.width = 3;
    image.height = 2;
    image.pixels = {0, 0, 255, 8, 0, 255, 8, 16, 255, 255, 16, 255, 255, 16, 255, 0, 0, 255};
    const LevelHistogram h = level_histogram(image, 5);
    ASSERT_EQ(h.counts[0].size(), 32u);
    long total = 0;
    for (long n : h.counts[0]) total += n;
    EXPECT_EQ(total, 6);
    EXPECT_EQ(h.counts[0][0], 2);
    EXPECT_EQ(h.counts[0][1], 2);   // png 8 = level 1 of 31 (8.23 rounded)
    EXPECT_EQ(h.counts[0][31], 2);
    EXPECT_EQ(h.used[0], 3);
    EXPECT_EQ(h.used[1], 2);        // 0 and 16 (level 2)
    EXPECT_EQ(h.used[2], 1);
}

TEST(PixelProbe, PickerFindsTheObjectUnderAPixelAndItsNormal) {
    const Scene scene = load_scene_file(test::source_path("scenes/fig10.json"));
    const ScenePicker picker(scene);
    const int w = scene.display.width, h = scene.display.height;
    EXPECT_EQ(picker.pick(0, 0).object, -1);
    const PixelHit centre = picker.pick(w / 2, h / 2);
    ASSERT_GE(centre.object, 0);
    const Object& object = scene.objects[std::size_t(centre.object)];
    EXPECT_NEAR(glm::length(centre.P - object.center), object.radius, 1e-9) << "on the sphere";
    EXPECT_NEAR(glm::length(centre.N), 1.0, 1e-12);
    EXPECT_GT(glm::dot(centre.N, centre.V), 0.0) << "a front face";
    const std::vector<int> ids = picker.object_ids();
    ASSERT_EQ(ids.size(), std::size_t(w) * h);
    EXPECT_EQ(ids[std::size_t(h / 2) * w + w / 2], centre.object);
    for (int i = 0; i < static_cast<int>(scene.objects.size()); ++i)
        EXPECT_NE(std::find(ids.begin(), ids.end(), i), ids.end()) << "object " << i << " is on the display";
}

}  // namespace
}  // namespace m3055
