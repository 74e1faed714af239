// `m3055 compare` and grading/level_compare: level
// differences counted exactly on crafted images, thresholds at their edges,
// the exit codes, and PNG vs PFM vs scene of the same picture.
#include "grading/comparison_json.h"
#include "grading/diff_image.h"
#include "grading/level_compare.h"
#include "image/image.h"
#include "image/quantize.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <set>
#include <nlohmann/json.hpp>

using namespace m3055;
using namespace m3055::grading;

namespace {

// A w x h image of 5-bit levels, every channel at `level`.
LevelImage flat(int w, int h, int level) {
    LevelImage image;
    image.width = w;
    image.height = h;
    image.bits = 5;
    image.levels.assign(std::size_t(w) * std::size_t(h) * 3, std::uint8_t(level));
    return image;
}

Rgb8Image to_png(const LevelImage& image) {
    Rgb8Image png{image.width, image.height, {}};
    for (std::uint8_t level : image.levels) png.pixels.push_back(level_to_png(level, image.bits));
    return png;
}

}  // namespace

TEST(LevelCompare, IdenticalImagesPassWithEveryPixelOnItsLevel) {
    const Comparison c = compare_levels(flat(8, 4, 17), flat(8, 4, 17));
    EXPECT_EQ(c.verdict, Verdict::pass);
    EXPECT_EQ(c.same_pixels, 32u);
    EXPECT_EQ(c.max_levels, 0);
    for (const auto& channel : c.histogram) {
        ASSERT_EQ(channel.size(), 32u);
        EXPECT_EQ(channel[0], 32u);
    }
}

TEST(LevelCompare, OnePixelOneLevelOffInOneChannel) {
    LevelImage b = flat(8, 4, 17);
    b.levels[3 * 5 + 1] = 18;  // pixel 5, green
    const Comparison c = compare_levels(flat(8, 4, 17), b);
    EXPECT_EQ(c.same_pixels, 31u);
    EXPECT_EQ(c.max_levels, 1);
    EXPECT_EQ(c.histogram[1][1], 1u);
    EXPECT_EQ(c.histogram[1][0], 31u);
    EXPECT_EQ(c.histogram[0][0], 32u);
    EXPECT_EQ(c.over_fail, 1u);
    EXPECT_EQ(c.verdict, Verdict::fail);  // default: any pixel off fails
}

TEST(LevelCompare, AWholeChannelOff) {
    LevelImage b = flat(10, 10, 3);
    for (std::size_t p = 0; p < 100; ++p) b.levels[3 * p + 2] = 10;  // blue 7 levels off everywhere
    const Comparison c = compare_levels(flat(10, 10, 3), b);
    EXPECT_EQ(c.same_pixels, 0u);
    EXPECT_EQ(c.histogram[2][7], 100u);
    EXPECT_EQ(c.histogram[0][0], 100u);
    EXPECT_EQ(c.max_levels, 7);
}

TEST(LevelCompare, ThresholdsAtTheirEdges) {
    LevelImage b = flat(10, 10, 10);
    b.levels[0] = 12;  // one pixel of 100 (1 %) two levels off
    const LevelImage a = flat(10, 10, 10);
    EXPECT_EQ(compare_levels(a, b, {{2, 0.0}, {}}).verdict, Verdict::pass);  // 2 levels allowed
    EXPECT_EQ(compare_levels(a, b, {{1, 0.0}, {}}).verdict, Verdict::fail);  // 1 % over, 0 % allowed
    EXPECT_EQ(compare_levels(a, b, {{1, 1.0}, {}}).verdict, Verdict::pass);  // exactly 1 %: passes
    EXPECT_EQ(compare_levels(a, b, {{1, 0.99}, {}}).verdict, Verdict::fail);
    EXPECT_EQ(compare_levels(a, b, {{2, 0.0}, Threshold{1, 0.0}}).verdict, Verdict::warn);
    EXPECT_EQ(compare_levels(a, b, {{2, 0.0}, Threshold{1, 1.0}}).verdict, Verdict::pass);
    EXPECT_EQ(compare_levels(a, b, {{1, 0.0}, Threshold{0, 0.0}}).verdict, Verdict::fail);  // fail wins
}

// A line that prints a share to two decimals never says 100.00 % while pixels are off,
// nor 0.00 % while some are not.
TEST(LevelCompare, PercentsToTwoPlacesNeverRoundToAllOrNone) {
    EXPECT_EQ(percent_to_two_places(163838, 163840), 99.99);  // 99.9988 %
    EXPECT_EQ(percent_to_two_places(163840, 163840), 100.0);
    EXPECT_EQ(percent_to_two_places(2, 163840), 0.01);  // 0.0012 %
    EXPECT_EQ(percent_to_two_places(0, 163840), 0.0);
    EXPECT_DOUBLE_EQ(percent_to_two_places(1, 4), 25.0);
    EXPECT_EQ(percent_to_two_places(0, 0), 100.0);
}

TEST(LevelCompare, SizesDifferIsAnErrorNamingBoth) {
    try {
        compare_levels(flat(512, 320, 0), flat(256, 160, 0));
        FAIL() << "no error";
    } catch (const CompareError& e) {
        EXPECT_STREQ(e.what(), "sizes differ: A is 512 x 320, B is 256 x 160");
    }
}

TEST(LevelCompare, PngLevelsRoundTripForEveryBitDepth) {
    for (int bits = 1; bits <= 8; ++bits)
        for (int level = 0; level < (1 << bits); ++level) {
            const Rgb8Image png{1, 1, {level_to_png(level, bits), 0, level_to_png(level, bits)}};
            EXPECT_EQ(levels_from_png(png, bits).levels[0], level) << bits << " bits";
        }
}

// levels_from_png computes round(v * top / 255) in integers: every byte value, every depth.
TEST(LevelCompare, PngBytesMapToTheNearestLevelForEveryByteAndDepth) {
    Rgb8Image png{256, 1, {}};
    for (int v = 0; v < 256; ++v) png.pixels.insert(png.pixels.end(), 3, std::uint8_t(v));
    for (int bits = 1; bits <= 8; ++bits) {
        const LevelImage levels = levels_from_png(png, bits);
        for (int v = 0; v < 256; ++v)
            ASSERT_EQ(levels.levels[3 * std::size_t(v)], std::lround(v * double((1 << bits) - 1) / 255.0))
                << v << " at " << bits << " bits";
    }
}

// The counts (skipping runs of equal pixels) against a plain count, on images
// with long equal runs and scattered differences at every position in a run.
TEST(LevelCompare, CountsEqualAPlainCountPixelByPixel) {
    LevelImage a = flat(97, 31, 7), b = a;
    std::uint32_t seed = 12345;
    const auto next = [&seed]() { return seed = seed * 1664525u + 1013904223u; };
    for (int k = 0; k < 300; ++k) b.levels[(next() >> 8) % b.levels.size()] = std::uint8_t((next() >> 8) % 32);
    for (std::size_t i = 0; i < 48; ++i) b.levels[b.levels.size() - 1 - i] = 31;  // the tail, past the last whole run
    const Comparison c = compare_levels(a, b, Thresholds{{2, 0.0}, Threshold{5, 0.0}});
    std::uint64_t same = 0, over_fail = 0, over_warn = 0, histogram[3][32] = {};
    int largest = 0;
    for (std::size_t p = 0; p < c.pixels; ++p) {
        int off = 0;
        for (int ch = 0; ch < 3; ++ch) {
            const int d = std::abs(int(a.levels[3 * p + std::size_t(ch)]) - int(b.levels[3 * p + std::size_t(ch)]));
            ++histogram[ch][d];
            off = std::max(off, d);
        }
        same += off == 0;
        over_fail += off > 2;
        over_warn += off > 5;
        largest = std::max(largest, off);
    }
    EXPECT_EQ(c.same_pixels, same);
    EXPECT_EQ(c.over_fail, over_fail);
    EXPECT_EQ(c.over_warn, over_warn);
    EXPECT_EQ(c.max_levels, largest);
    for (int ch = 0; ch < 3; ++ch)
        EXPECT_EQ(c.histogram[ch], std::vector<std::uint64_t>(histogram[ch], histogram[ch] + 32)) << ch;
}

TEST(LevelCompare, PfmLinearStatsAndRowOrder) {
    RgbFloatImage a{2, 2, std::vector<float>(12, 0.5f)};
    RgbFloatImage b = a;
    b.pixels[0] = 0.6f;  // bottom-left red in PFM order: top-to-bottom row 1
    const LevelImage la = levels_from_pfm(a, 5), lb = levels_from_pfm(b, 5);
    EXPECT_EQ(lb.levels[3 * 2], quantize_level(0.6, 5));
    const Comparison c = compare_levels(la, lb);
    ASSERT_TRUE(c.linear);
    EXPECT_NEAR(c.linear->max_abs, 0.1, 1e-6);
    EXPECT_NEAR(c.linear->mean_abs, 0.1 / 12, 1e-7);
    EXPECT_NEAR(c.linear->rms, std::sqrt(0.01 / 12), 1e-7);
    EXPECT_NEAR(c.linear->psnr_db, 10 * std::log10(12 / 0.01), 1e-4);
    EXPECT_EQ(to_json(c)["linear"]["max_abs"].get<double>(), c.linear->max_abs);
}

TEST(DiffImage, ColoursByLevelsOffWithALegendBand) {
    LevelImage b = flat(512, 10, 0);  // wider than the legend: not enlarged
    b.levels[0] = 1;               // pixel (0,0) one level off
    b.levels[3 * 1 + 0] = 9;       // pixel (1,0) nine levels off
    const Rgb8Image image = difference_image(flat(512, 10, 0), b);
    EXPECT_EQ(image.width, 512);
    EXPECT_EQ(image.height, 10 + kLegendHeight);
    std::uint8_t one[3], nine[3];
    diff_colour(1, one);
    diff_colour(9, nine);
    EXPECT_TRUE(std::equal(one, one + 3, image.pixels.begin()));
    EXPECT_TRUE(std::equal(nine, nine + 3, image.pixels.begin() + 3));
    // Unchanged pixels are grey (the dimmed A), never a class colour.
    EXPECT_EQ(image.pixels[6], image.pixels[7]);
    EXPECT_EQ(image.pixels[7], image.pixels[8]);
}

// A 16 x 8 image is drawn a whole number of times larger, each pixel a square block.
TEST(DiffImage, AnImageNarrowerThanTheLegendIsEnlargedByAWholeFactor) {
    LevelImage b = flat(16, 8, 0);
    b.levels[3 * 1] = 1;  // pixel (1,0) one level off
    const Rgb8Image image = difference_image(flat(16, 8, 0), b);
    const int scale = (image.height - kLegendHeight) / 8;
    ASSERT_GT(scale, 1);
    EXPECT_EQ((image.height - kLegendHeight) % 8, 0);
    EXPECT_GE(image.width, 16 * scale);
    std::uint8_t one[3];
    diff_colour(1, one);
    const auto at = [&](int x, int y) { return image.pixels.begin() + (std::ptrdiff_t(y) * image.width + x) * 3; };
    for (int y = 0; y < scale; ++y)
        for (int x = 0; x < 3 * scale; ++x)
            EXPECT_EQ(std::equal(one, one + 3, at(x, y)), x >= scale && x < 2 * scale) << x << ", " << y;
    EXPECT_FALSE(std::equal(one, one + 3, at(scale, scale)));  // the next row of pixels
}

// An unchanged pixel is A's luma dimmed, 20 + 60 * luma (from a table at low depths): every colour at 3 bits.
TEST(DiffImage, UnchangedPixelsAreADimmedGreyOfA) {
    LevelImage a;
    a.width = 512;
    a.height = 1;
    a.bits = 3;
    for (int r = 0; r < 8; ++r)
        for (int g = 0; g < 8; ++g)
            for (int b = 0; b < 8; ++b) a.levels.insert(a.levels.end(), {std::uint8_t(r), std::uint8_t(g), std::uint8_t(b)});
    const Rgb8Image image = difference_image(a, a);
    for (std::size_t p = 0; p < 512; ++p) {
        const double luma = (0.2126 * a.levels[3 * p] + 0.7152 * a.levels[3 * p + 1] + 0.0722 * a.levels[3 * p + 2]) / 7;
        ASSERT_EQ(image.pixels[3 * p], std::uint8_t(20 + luma * 60.0)) << p;
    }
}

// ---- The command --------------------------------------------------------------

namespace {

struct Files {
    test::TempDir dir;
    std::string png_a, png_b, png_small;
    Files() {
        LevelImage b = flat(16, 8, 12);
        b.levels[0] = 14;
        png_a = dir.file("a.png");
        png_b = dir.file("b.png");
        png_small = dir.file("small.png");
        write_png(png_a, to_png(flat(16, 8, 12)));
        write_png(png_b, to_png(b));
        write_png(png_small, to_png(flat(8, 8, 12)));
    }
};

}  // namespace

TEST(CompareCommand, ExitCodesPassFailWarnError) {
    Files f;
    EXPECT_EQ(test::run_m3055({"compare", f.png_a, f.png_a}).exit_code, 0);
    EXPECT_EQ(test::run_m3055({"compare", f.png_a, f.png_b}).exit_code, 1);
    EXPECT_EQ(test::run_m3055({"compare", f.png_a, f.png_b, "--fail-levels", "2"}).exit_code, 0);
    const auto warn = test::run_m3055({"compare", f.png_a, f.png_b, "--fail-levels", "2", "--warn-levels", "1"});
    EXPECT_EQ(warn.exit_code, 1);
    EXPECT_NE(warn.out.find("warn:"), std::string::npos) << warn.out;
    // 1 pixel of 128 is 0.78125 %.
    EXPECT_EQ(test::run_m3055({"compare", f.png_a, f.png_b, "--fail-percent", "0.78125"}).exit_code, 0);
    EXPECT_EQ(test::run_m3055({"compare", f.png_a, f.png_b, "--fail-percent", "0.78"}).exit_code, 1);
    const auto sizes = test::run_m3055({"compare", f.png_a, f.png_small});
    EXPECT_EQ(sizes.exit_code, 2);
    EXPECT_NE(sizes.err.find("A is 16 x 8, B is 8 x 8"), std::string::npos) << sizes.err;
    EXPECT_EQ(test::run_m3055({"compare", f.png_a, f.dir.file("missing.png")}).exit_code, 2);
}

TEST(CompareCommand, JsonIsOneObjectAndDiffIsWritten) {
    Files f;
    const std::string diff = f.dir.file("diff.png");
    const auto run = test::run_m3055({"compare", f.png_a, f.png_b, "--json", "--diff", diff});
    EXPECT_EQ(run.exit_code, 1) << run.err;
    const nlohmann::json result = nlohmann::json::parse(run.out);
    EXPECT_EQ(result["result"], "fail");
    EXPECT_EQ(result["same_pixels"], 127);
    EXPECT_EQ(result["max_levels"], 2);
    EXPECT_EQ(result["histogram"]["r"][2], 1);
    const Rgb8Image image = read_png(diff);
    EXPECT_EQ(image.height, 8 * 8 + kLegendHeight);  // 16 x 8, enlarged 8 times (narrower than the legend)
    // --diff may not overwrite an input.
    EXPECT_EQ(test::run_m3055({"compare", f.png_a, f.png_b, "--diff", f.png_a}).exit_code, 2);
}

// The legend's font (grading/legend_font.h) missing: one line naming the
// file and the package, and the difference image is still written (in the
// 3 x 5 letters), the same size.
TEST(CompareCommand, MissingLegendFontIsOneLineAndTheDiffIsStillWritten) {
    Files f;
    const std::string diff = f.dir.file("diff.png"), font = f.dir.file("no-such-font.ttf");
    setenv("M3055_LEGEND_FONT", font.c_str(), 1);
    const auto run = test::run_m3055({"compare", f.png_a, f.png_b, "--diff", diff});
    unsetenv("M3055_LEGEND_FONT");
    EXPECT_EQ(run.exit_code, 1) << run.err;  // the images differ: as with the font
    EXPECT_NE(run.err.find("m3055: warning: " + font + ": cannot read the file (the difference legend's font; Debian: "
                           "apt-get install fonts-dejavu-core, or set M3055_LEGEND_FONT)"),
              std::string::npos)
        << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_EQ(read_png(diff).height, 8 * 8 + kLegendHeight);
}

// With the font, the legend's text is anti-aliased: grey levels between the
// band's black and the text's white, which the 3 x 5 letters never make.
TEST(DiffImage, LegendTextIsDrawnWithARealFont) {
    const Rgb8Image image = difference_image(flat(512, 4, 0), flat(512, 4, 0));
    std::set<int> greys;
    for (int y = 4; y < image.height; ++y)
        for (int x = 0; x < 120; ++x) {  // "levels off:"
            const std::uint8_t* p = &image.pixels[(std::size_t(y) * 512 + std::size_t(x)) * 3];
            if (p[0] == p[1] && p[1] == p[2] && p[0] > 0 && p[0] < 255) greys.insert(p[0]);
        }
    EXPECT_GT(greys.size(), 20u) << "the legend's font is missing? (fonts-dejavu-core)";
}

TEST(CompareCommand, SceneAgainstItsOwnPngAndPfm) {
    test::TempDir dir;
    const std::string scene = test::source_path("scenes/spec_example.json");
    ASSERT_EQ(test::run_m3055({"render", "--scene", scene, "--out", dir.file("s.png"), "--raw", dir.file("s.pfm")})
                  .exit_code,
              0);
    for (const std::string other : {"s.png", "s.pfm"}) {
        const auto run = test::run_m3055({"compare", scene, dir.file(other), "--json"});
        EXPECT_EQ(run.exit_code, 0) << other << ": " << run.err << run.out;
        const nlohmann::json result = nlohmann::json::parse(run.out);
        EXPECT_EQ(result["same_percent"], 100.0);
        if (other == "s.pfm") {
            EXPECT_EQ(result["linear"]["max_abs"], 0.0);
        }
    }
    // A PFM quantized on the CPU lands on the same levels as the GPU's PNG.
    EXPECT_EQ(test::run_m3055({"compare", dir.file("s.png"), dir.file("s.pfm")}).exit_code, 0);
}

// ---- Two folders by name --------------------------------------------------------

namespace {

// A and B: a pair that matches (its name with a space), a pair one pixel
// two levels apart, a pair of different sizes, a name in each folder alone,
// and what is not a PNG file (a text file, a folder named *.png) in both.
struct Folders {
    test::TempDir dir;
    std::string a = dir.file("A"), b = dir.file("B");
    Folders(bool with_sizes_differing = true) {
        std::filesystem::create_directory(a);
        std::filesystem::create_directory(b);
        LevelImage off = flat(16, 8, 12);
        off.levels[0] = 14;
        write_png(a + "/same one.png", to_png(flat(16, 8, 12)));
        write_png(b + "/same one.png", to_png(flat(16, 8, 12)));
        write_png(a + "/off.png", to_png(flat(16, 8, 12)));
        write_png(b + "/off.png", to_png(off));
        if (with_sizes_differing) {
            write_png(a + "/size.PNG", to_png(flat(16, 8, 12)));
            write_png(b + "/size.PNG", to_png(flat(8, 8, 12)));
        }
        write_png(a + "/only-a.png", to_png(flat(16, 8, 3)));
        write_png(b + "/only-b.png", to_png(flat(16, 8, 3)));
        for (const std::string& folder : {a, b}) {
            std::ofstream(folder + "/notes.txt") << "not an image\n";
            std::filesystem::create_directory(folder + "/renders.png");
        }
    }
};

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

}  // namespace

TEST(CompareFolders, EveryPairThatDoesNotPassThenOneSummaryLine) {
    Folders f;
    const auto run = test::run_m3055({"compare", f.a, f.b});
    EXPECT_EQ(run.exit_code, 2) << run.err;  // a pair could not be compared
    EXPECT_EQ(run.err, "");
    const std::vector<std::string> lines = lines_of(run.out);
    ASSERT_EQ(lines.size(), 5u) << run.out;
    EXPECT_EQ(lines[0].rfind("off.png: fail:", 0), 0u) << lines[0];
    EXPECT_EQ(lines[1], "error: size.PNG: sizes differ: A is 16 x 8, B is 8 x 8") << run.out;
    EXPECT_EQ(lines[2], "only in A: only-a.png");
    EXPECT_EQ(lines[3], "only in B: only-b.png");
    EXPECT_EQ(lines[4],
              "3 PNGs in both folders: 1 pass, 0 warn, 1 fail, 1 could not be compared; 1 only in A, 1 only in B");
}

// The summary line's "on another" counts every pixel not on the same level; with
// --fail-levels N > 0 it also says how many are beyond N, the ones that fail.
TEST(CompareCommand, TheSummaryLineSaysWhichPixelsFail) {
    Files f;  // one pixel of 128 two levels off
    const auto last_line = [](const std::string& out) {
        const std::size_t end = out.find_last_not_of('\n');
        return out.substr(out.rfind('\n', end) + 1, end - out.rfind('\n', end));
    };
    EXPECT_EQ(last_line(test::run_m3055({"compare", f.png_a, f.png_b}).out),
              "fail: 99.22 % of pixels on the same level, 1 on another (max 2 levels)");
    EXPECT_EQ(last_line(test::run_m3055({"compare", f.png_a, f.png_b, "--fail-levels", "1"}).out),
              "fail: 99.22 % of pixels on the same level, 1 on another (max 2 levels), 1 more than 1 level off");
    EXPECT_EQ(last_line(test::run_m3055({"compare", f.png_a, f.png_b, "--fail-levels", "2"}).out),
              "pass: 99.22 % of pixels on the same level, 1 on another (max 2 levels), 0 more than 2 levels off");
    // "Over 99.5 % on the same level, none more than one off" in one command.
    const auto target = test::run_m3055(
        {"compare", f.png_a, f.png_b, "--fail-levels", "1", "--warn-levels", "0", "--warn-percent", "0.5"});
    EXPECT_EQ(target.exit_code, 1);
}

TEST(CompareFolders, ExitStatusFollowsThePairsAndTheThresholds) {
    Folders f(false);
    EXPECT_EQ(test::run_m3055({"compare", f.a, f.b}).exit_code, 1);
    // The pair within two levels passes, but a name in one folder only is still a difference.
    EXPECT_EQ(test::run_m3055({"compare", f.a, f.b, "--fail-levels", "2"}).exit_code, 1);
    std::filesystem::remove(f.a + "/only-a.png");
    std::filesystem::remove(f.b + "/only-b.png");
    const auto pass = test::run_m3055({"compare", f.a, f.b, "--fail-levels", "2"});
    EXPECT_EQ(pass.exit_code, 0) << pass.err;
    EXPECT_EQ(pass.out, "2 PNGs in both folders: 2 pass, 0 warn, 0 fail, 0 could not be compared; 0 only in A, 0 only "
                        "in B\n");
    EXPECT_EQ(test::run_m3055({"compare", f.a, f.b, "--fail-levels", "2", "--warn-levels", "1"}).exit_code, 1);
}

TEST(CompareFolders, JsonIsOneObjectWithEveryPair) {
    Folders f;
    const auto run = test::run_m3055({"compare", f.a, f.b, "--json"});
    EXPECT_EQ(run.exit_code, 2) << run.err;
    const nlohmann::json result = nlohmann::json::parse(run.out);
    ASSERT_EQ(result["pairs"].size(), 3u) << run.out;
    EXPECT_EQ(result["pairs"][0]["name"], "off.png");
    EXPECT_EQ(result["pairs"][0]["result"], "fail");
    EXPECT_EQ(result["pairs"][0]["same_pixels"], 127);
    EXPECT_EQ(result["pairs"][1]["name"], "same one.png");
    EXPECT_EQ(result["pairs"][1]["result"], "pass");
    EXPECT_EQ(result["pairs"][2]["name"], "size.PNG");
    EXPECT_EQ(result["pairs"][2]["result"], "error");
    EXPECT_EQ(result["only_a"], nlohmann::json::array({"only-a.png"}));
    EXPECT_EQ(result["only_b"], nlohmann::json::array({"only-b.png"}));
    EXPECT_EQ(result["summary"], nlohmann::json({{"pass", 1}, {"warn", 0}, {"fail", 1}, {"error", 1}}));
}

TEST(CompareFolders, AFolderAndAnImageOrDiffAreOneLineAndExit2) {
    Folders f;
    const std::string png = f.a + "/off.png";
    const std::vector<std::vector<std::string>> calls = {
        {"compare", f.a, png}, {"compare", png, f.b}, {"compare", f.a, f.b, "--diff", f.dir.file("diff.png")}};
    for (const std::vector<std::string>& args : calls) {
        const auto run = test::run_m3055(args);
        EXPECT_EQ(run.exit_code, 2) << args[2];
        EXPECT_EQ(run.out, "") << args[2];
        EXPECT_EQ(run.err.rfind("m3055: compare: ", 0), 0u) << run.err;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    }
    EXPECT_FALSE(std::filesystem::exists(f.dir.file("diff.png")));
}
