#include "grading/level_compare.h"

#include "image/quantize.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace m3055::grading {

namespace {

int max_level(int bits) { return (1 << bits) - 1; }

// PFM rows are bottom to top; levels and linear are kept top to bottom.
std::vector<float> flipped_rows(const RgbFloatImage& image) {
    std::vector<float> out(image.pixels.size());
    const std::size_t row = std::size_t(image.width) * 3;
    for (int y = 0; y < image.height; ++y)
        std::copy_n(image.pixels.begin() + std::ptrdiff_t(row * std::size_t(image.height - 1 - y)), row,
                    out.begin() + std::ptrdiff_t(row * std::size_t(y)));
    return out;
}

std::string size_text(int width, int height) { return std::to_string(width) + " x " + std::to_string(height); }

LinearStats linear_stats(const std::vector<float>& a, const std::vector<float>& b) {
    LinearStats stats;
    double sum = 0, sum_sq = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double d = std::abs(double(a[i]) - double(b[i]));
        stats.max_abs = std::max(stats.max_abs, d);
        sum += d;
        sum_sq += d * d;
    }
    const double n = a.empty() ? 1.0 : double(a.size());
    stats.mean_abs = sum / n;
    const double mse = sum_sq / n;
    stats.rms = std::sqrt(mse);
    stats.psnr_db = mse > 0 ? 10.0 * std::log10(1.0 / mse) : std::numeric_limits<double>::infinity();
    return stats;
}

}  // namespace

void check_same_size(int a_width, int a_height, int b_width, int b_height) {
    if (a_width != b_width || a_height != b_height)
        throw CompareError("sizes differ: A is " + size_text(a_width, a_height) + ", B is " +
                           size_text(b_width, b_height));
}

void check_comparable(const LevelImage& a, const LevelImage& b) {
    check_same_size(a.width, a.height, b.width, b.height);
    if (a.bits != b.bits)
        throw CompareError("bit depths differ: A has " + std::to_string(a.bits) + " bits a channel, B has " +
                           std::to_string(b.bits));
}

const char* to_string(Verdict verdict) {
    switch (verdict) {
        case Verdict::pass: return "pass";
        case Verdict::warn: return "warn";
        case Verdict::fail: return "fail";
    }
    return "?";
}

LevelImage levels_from_png(const Rgb8Image& png, int bits) {
    LevelImage image{png.width, png.height, bits, {}, {}, {}};
    image.levels.resize(png.pixels.size());
    // round(v * top / 255) in 16-bit adds and shifts, which the compiler
    // vectorizes (this runs for every byte of every submission):
    // floor((v top + 127) / 255) is it exactly, as v * top / 255 is never
    // halfway between two integers (2 v top would be an odd multiple of 255),
    // and floor(x / 255) = (x + 1 + (x >> 8)) >> 8 for every x <= 65152 there
    // is. compare_test checks every byte value at every depth.
    const std::uint16_t top = std::uint16_t(max_level(bits));
    const std::uint8_t* in = png.pixels.data();
    std::uint8_t* out = image.levels.data();
    const std::size_t n = png.pixels.size();  // not reloaded through `out` (bytes may alias anything)
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint16_t x = std::uint16_t(in[i] * top + 127);
        out[i] = std::uint8_t(std::uint16_t(x + 1 + (x >> 8)) >> 8);
    }
    return image;
}

Rgb8Image display_of(const LevelImage& levels) {
    Rgb8Image image{levels.width, levels.height, {}};
    std::uint8_t png_of[256] = {};
    for (int level = 0; level <= max_level(levels.bits); ++level) png_of[level] = level_to_png(level, levels.bits);
    image.pixels.resize(levels.levels.size());
    for (std::size_t i = 0; i < levels.levels.size(); ++i) image.pixels[i] = png_of[levels.levels[i]];
    return image;
}

LevelImage levels_from_pfm(const RgbFloatImage& pfm, int bits) {
    LevelImage image{pfm.width, pfm.height, bits, {}, flipped_rows(pfm), {}};
    image.levels.resize(image.linear.size());
    for (std::size_t i = 0; i < image.linear.size(); ++i)
        image.levels[i] = std::uint8_t(quantize_level(double(image.linear[i]), bits));
    return image;
}

LevelImage levels_from_render(const Rgb8Image& display, const RgbFloatImage& raw, int bits) {
    LevelImage image = levels_from_png(display, bits);
    if (raw.width != display.width || raw.height != display.height)
        throw CompareError("the render's display and raw images differ in size");
    image.linear = flipped_rows(raw);
    return image;
}

std::vector<int> levels_off(const LevelImage& a, const LevelImage& b) {
    check_comparable(a, b);
    std::vector<int> off(std::size_t(a.width) * std::size_t(a.height), 0);
    for (std::size_t p = 0; p < off.size(); ++p)
        for (std::size_t c = 0; c < 3; ++c)
            off[p] = std::max(off[p], std::abs(int(a.levels[3 * p + c]) - int(b.levels[3 * p + c])));
    return off;
}

Comparison compare_levels(const LevelImage& a, const LevelImage& b, const Thresholds& thresholds) {
    check_comparable(a, b);
    Comparison result;
    result.width = a.width;
    result.height = a.height;
    result.bits = a.bits;
    result.pixels = std::uint64_t(a.width) * std::uint64_t(a.height);
    result.thresholds = thresholds;
    // Counted in fixed arrays and copied out once: the inner loop is the
    // whole cost of grading beyond rendering.
    std::uint64_t histogram[3][256] = {};
    int largest = 0;
    const int fail_levels = thresholds.fail.levels;
    const int warn_levels = thresholds.warn ? thresholds.warn->levels : 256;
    const std::uint8_t* pa = a.levels.data();
    const std::uint8_t* pb = b.levels.data();
    // Most pixels of a graded render sit on the reference's level (the
    // background at least): they are only counted, and added to the
    // histograms' 0 bins at the end (one increment of the same bin per pixel
    // would chain every iteration through memory).
    std::uint64_t same = 0;
    constexpr std::size_t kBlock = 16;  // pixels compared at once where whole runs match
    for (std::size_t p = 0; p < result.pixels; ++p, pa += 3, pb += 3) {
        if (p % kBlock == 0 && p + kBlock <= result.pixels && std::memcmp(pa, pb, 3 * kBlock) == 0) {
            same += kBlock;
            p += kBlock - 1;
            pa += 3 * (kBlock - 1);
            pb += 3 * (kBlock - 1);
            continue;
        }
        if (pa[0] == pb[0] && pa[1] == pb[1] && pa[2] == pb[2]) {
            ++same;
            continue;
        }
        const int dr = pa[0] > pb[0] ? pa[0] - pb[0] : pb[0] - pa[0];
        const int dg = pa[1] > pb[1] ? pa[1] - pb[1] : pb[1] - pa[1];
        const int db = pa[2] > pb[2] ? pa[2] - pb[2] : pb[2] - pa[2];
        ++histogram[0][dr];
        ++histogram[1][dg];
        ++histogram[2][db];
        const int off = std::max(dr, std::max(dg, db));
        result.over_fail += off > fail_levels;
        result.over_warn += off > warn_levels;
        largest = std::max(largest, off);
    }
    result.max_levels = largest;
    result.same_pixels = same;
    for (auto& channel : histogram) channel[0] += same;
    for (int c = 0; c < 3; ++c)
        result.histogram[c].assign(histogram[c], histogram[c] + max_level(a.bits) + 1);
    if (a.has_linear() && b.has_linear()) result.linear = linear_stats(a.linear, b.linear);
    const double pixels = result.pixels ? double(result.pixels) : 1.0;
    if (100.0 * double(result.over_fail) / pixels > thresholds.fail.percent)
        result.verdict = Verdict::fail;
    else if (thresholds.warn && 100.0 * double(result.over_warn) / pixels > thresholds.warn->percent)
        result.verdict = Verdict::warn;
    return result;
}

double percent_to_two_places(std::uint64_t part, std::uint64_t whole) {
    if (whole == 0) return 100.0;
    const double percent = 100.0 * double(part) / double(whole);
    if (part > 0 && percent < 0.01) return 0.01;
    if (part < whole && percent > 99.99) return 99.99;
    return percent;
}

}  // namespace m3055::grading
