// The CPU reference against the independent reference images in
// tests/data/reference-images/ (JSON scene + raw PFM + quantized PNG each): away
// from silhouettes the raw colour must agree to 1e-4 and the quantized PNG
// exactly, but for rare pixels sitting on a level boundary (one level off).
#include "image/image.h"
#include "image/quantize.h"
#include "reference/reference.h"
#include "scene/load.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace m3055::ref {
namespace {

constexpr double kRawTolerance = 1e-4;

std::string reference_path(const std::string& name) { return test::reference_image_path(name); }
constexpr double kMinExactShare = 0.999;

// Every NAME.json in the folder that has its NAME.pfm and NAME.png beside it.
std::vector<std::string> reference_scene_names() {
    namespace fs = std::filesystem;
    std::vector<std::string> names;
    const fs::path dir = reference_path("");
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const fs::path p = entry.path();
        if (p.extension() != ".json") continue;
        fs::path pfm = p, png = p;
        if (fs::exists(pfm.replace_extension(".pfm")) && fs::exists(png.replace_extension(".png")))
            names.push_back(p.stem().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

TEST(ReferenceImages, FolderHoldsScenes) {
    EXPECT_GE(reference_scene_names().size(), 3u) << reference_path("");
}

class ReferenceImageFile : public ::testing::TestWithParam<std::string> {
protected:
    std::string path(const std::string& ext) const {
        return reference_path(GetParam() + ext);
    }
};

TEST_P(ReferenceImageFile, InteriorPixelsMatchTheRawAndQuantizedImages) {
    const Scene scene = load_scene_file(path(".json"), LoadContext::trusted());
    const ReferenceImage image = render_reference(scene);
    const RgbFloatImage pfm = read_pfm(path(".pfm"));
    const Rgb8Image png = read_png(path(".png"));
    const int w = image.width, h = image.height, bits = scene.display.bits;
    ASSERT_EQ(pfm.width, w);
    ASSERT_EQ(pfm.height, h);
    ASSERT_EQ(png.width, w);
    ASSERT_EQ(png.height, h);
    const int max_level = (1 << bits) - 1;

    double max_raw_diff = 0.0;
    long interior = 0, exact = 0, one_off = 0, worse = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (!is_interior(image, x, y)) continue;
            ++interior;
            const std::size_t top = std::size_t(y) * w + x;              // ours and PNG: top row first
            const std::size_t bottom = std::size_t(h - 1 - y) * w + x;   // PFM: bottom row first
            bool pixel_exact = true;
            int pixel_levels_off = 0;
            for (int c = 0; c < 3; ++c) {
                const double ours = image.rgb[3 * top + c];
                ASSERT_TRUE(std::isfinite(ours)) << "pixel " << x << "," << y;
                const double raw = pfm.pixels[3 * bottom + c];
                max_raw_diff = std::max(max_raw_diff, std::fabs(ours - raw));

                const int level = quantize_level(ours, bits);
                const int theirs = png.pixels[3 * top + c];
                const int their_level = int(std::lround(theirs * double(max_level) / 255.0));
                ASSERT_EQ(level_to_png(their_level, bits), theirs) << "not an M3055 level in the PNG";
                if (level_to_png(level, bits) != theirs) pixel_exact = false;
                pixel_levels_off = std::max(pixel_levels_off, std::abs(level - their_level));
            }
            exact += pixel_exact;
            one_off += pixel_levels_off == 1;
            worse += pixel_levels_off > 1;
        }
    }
    ASSERT_GT(interior, 0);
    const double exact_share = double(exact) / double(interior);
    std::cout << GetParam() << ": " << interior << " interior pixels, max |raw diff| = " << max_raw_diff
              << ", PNG exact " << exact << " (" << 100.0 * exact_share << "%), one level off " << one_off
              << ", more " << worse << "\n";
    RecordProperty("max_raw_diff", std::to_string(max_raw_diff));
    RecordProperty("png_exact_share", std::to_string(exact_share));
    EXPECT_LE(max_raw_diff, kRawTolerance);
    EXPECT_GE(exact_share, kMinExactShare);
    EXPECT_EQ(worse, 0);
}

INSTANTIATE_TEST_SUITE_P(Scenes, ReferenceImageFile, ::testing::ValuesIn(reference_scene_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(ReferenceImageFile);

}  // namespace
}  // namespace m3055::ref
