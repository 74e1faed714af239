// Comparing two images at the display's own precision: what a
// teacher needs to know about a student's render is how many pixels land on a
// different level of the emulated display, and by how many levels; with the
// linear (PFM) colour also the classic max / mean / RMS difference and PSNR.
// `m3055 compare`, `m3055 grade` and the explorer all use these functions.
#pragma once

#include "image/image.h"

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace m3055::grading {

// An image as display levels (0 .. 2^bits - 1 per channel), rows top to
// bottom, and, when known (a PFM or a render), its linear colour in the same
// order. Made by the functions below.
struct LevelImage {
    int width = 0, height = 0, bits = 5;
    std::vector<std::uint8_t> levels;  // width * height * 3
    std::vector<float> linear;         // width * height * 3, or empty
    bool has_linear() const { return !linear.empty(); }
    // A reference's region (assignment "region": "objects"): 1 for each
    // pixel, rows top to bottom, that is compared; empty: every pixel.
    std::vector<std::uint8_t> region;
};

// A PNG's bytes mapped back to levels: level = round(png * (2^bits - 1) / 255),
// the inverse of docs/spec.md#2-display's png = round(level * 255 / (2^bits - 1))
// (exact for every bits in 1..8; a value between two levels goes to the nearer).
LevelImage levels_from_png(const Rgb8Image& png, int bits);
// A PFM's linear colour (rows bottom to top, as PFM stores them) quantized as
// the display does (image/quantize.h, no dithering), linear kept.
LevelImage levels_from_pfm(const RgbFloatImage& pfm, int bits);
// A render: the display image as the renderer quantized it (dithering
// included) plus its linear colour. Both must be the same size.
LevelImage levels_from_render(const Rgb8Image& display, const RgbFloatImage& raw, int bits);

// The display image of `levels` (png = round(level * 255 / (2^bits - 1))):
// exactly the bytes the renderer reads back for the same levels.
Rgb8Image display_of(const LevelImage& levels);

// When two images differ too much (OpenImageIO idiff's -fail/-failpercent,
// -warn/-warnpercent): a pixel is "over" a threshold when one of its channels
// is more than `levels` levels off; the comparison fails (warns) when the
// share of such pixels is more than `percent` %. Exactly at the edge passes.
struct Threshold {
    int levels = 0;
    double percent = 0.0;
};
struct Thresholds {
    Threshold fail;                 // default: any pixel off by a level fails
    std::optional<Threshold> warn;  // default: none (a comparison that does not fail passes)
};

enum class Verdict { pass, warn, fail };
const char* to_string(Verdict verdict);

struct LinearStats {
    double max_abs = 0, mean_abs = 0, rms = 0;
    // 10 log10(1 / MSE), peak 1 (display white); infinite when identical.
    double psnr_db = 0;
};

struct Comparison {
    int width = 0, height = 0, bits = 5;
    // "": every pixel of the width x height compared; "objects": only the
    // pixels the reference's objects cover (`pixels` of them).
    std::string region;
    std::uint64_t pixels = 0;
    std::uint64_t same_pixels = 0;  // all three channels on the same level
    // histogram[c][k]: pixels whose channel c is k levels off (k = 0 .. 2^bits - 1).
    std::vector<std::uint64_t> histogram[3];
    int max_levels = 0;                // the largest difference, any channel
    std::uint64_t over_fail = 0;       // pixels over thresholds.fail.levels
    std::uint64_t over_warn = 0;       // pixels over thresholds.warn's levels (0 without warn)
    std::optional<LinearStats> linear;  // when both images have linear colour
    Thresholds thresholds;
    Verdict verdict = Verdict::pass;
    double same_share() const { return pixels ? double(same_pixels) / double(pixels) : 1.0; }
};

// 100 part / whole for a line that prints it to two decimals: never "100.00" unless part is
// whole, nor "0.00" unless it is 0 ("fail: 100.00 % of pixels on the same level, 2 on
// another" read as a contradiction). 100 when whole is 0.
double percent_to_two_places(std::uint64_t part, std::uint64_t whole);

// Thrown for images that cannot be compared; what() is one line naming both
// sizes ("sizes differ: A is 512 x 320, B is 256 x 160") or both bit depths.
class CompareError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws CompareError unless a and b have the same size and bit depth.
void check_comparable(const LevelImage& a, const LevelImage& b);
// Its size half, for images of any kind: CompareError "sizes differ: A is W x H, B is W x H".
void check_same_size(int a_width, int a_height, int b_width, int b_height);

Comparison compare_levels(const LevelImage& a, const LevelImage& b, const Thresholds& thresholds = {});

// Per pixel, the largest level difference of its three channels.
std::vector<int> levels_off(const LevelImage& a, const LevelImage& b);

}  // namespace m3055::grading
