#include "grading/ab_compare.h"

#include "grading/level_compare.h"

#include <algorithm>
#include <cstdlib>
#include <string>

namespace m3055::grading {

LevelDifference level_difference(const Rgb8Image& a, const Rgb8Image& b, int bits) {
    const Comparison c = compare_levels(levels_from_png(a, bits), levels_from_png(b, bits));
    return {c.pixels, c.pixels - c.same_pixels};
}

int auto_difference_scale(const Rgb8Image& a, const Rgb8Image& b) {
    check_same_size(a.width, a.height, b.width, b.height);
    int largest = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) largest = std::max(largest, std::abs(a.pixels[i] - b.pixels[i]));
    return largest == 0 ? 1 : std::clamp(255 / largest, 1, kMaxDifferenceScale);
}

Rgb8Image scaled_difference(const Rgb8Image& a, const Rgb8Image& b, int scale) {
    check_same_size(a.width, a.height, b.width, b.height);
    scale = std::clamp(scale, 1, kMaxDifferenceScale);
    Rgb8Image out{a.width, a.height, std::vector<std::uint8_t>(a.pixels.size())};
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        out.pixels[i] = std::uint8_t(std::min(255, std::abs(a.pixels[i] - b.pixels[i]) * scale));
    return out;
}

}  // namespace m3055::grading
