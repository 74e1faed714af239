// The explorer's A/B split read-outs, ImGui-free so tests can hold
// them against headless renders:
//   - level_difference: how many pixels of B show another display level than
//     A (any channel), through level_compare.h's compare_levels, the comparison
//     `m3055 compare` and grading use (one definition of "differs");
//   - scaled_difference: the third pane, |A - B| per channel of the display
//     bytes times a whole scale, clamped to 255, so a one-level step (8 PNG
//     values at 5 bits) becomes visible.
#pragma once

#include "image/image.h"

#include <cstdint>

namespace m3055::grading {

struct LevelDifference {
    std::uint64_t pixels = 0;
    std::uint64_t differing = 0;  // pixels with a channel on another level
    double share() const { return pixels ? double(differing) / double(pixels) : 0.0; }
};
// Throws CompareError when the sizes differ.
LevelDifference level_difference(const Rgb8Image& a, const Rgb8Image& b, int bits);

inline constexpr int kMaxDifferenceScale = 255;
// The largest whole scale that keeps the largest |A - B| byte within 255
// (1 when A and B are the same, or already differ by more than 127).
int auto_difference_scale(const Rgb8Image& a, const Rgb8Image& b);
// Per channel min(255, |a - b| * scale); scale in [1, kMaxDifferenceScale].
// Throws CompareError when the sizes differ.
Rgb8Image scaled_difference(const Rgb8Image& a, const Rgb8Image& b, int scale);

}  // namespace m3055::grading
