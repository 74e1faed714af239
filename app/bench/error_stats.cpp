#include "error_stats.h"

#include "image/quantize.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace m3055::bench {

void ErrorAccumulator::add(const RgbFloatImage& image, const ref::ReferenceImage& reference, int bits) {
    const int w = reference.width, h = reference.height;
    if (image.width != w || image.height != h) throw std::runtime_error("bench: image and reference sizes differ");
    for (float value : image.pixels)
        if (!std::isfinite(value)) ++nonfinite_;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (!ref::is_interior(reference, x, y)) continue;
            ++pixels_;
            bool same = true;
            for (int c = 0; c < 3; ++c) {
                const double expected = reference.rgb[(std::size_t(y) * w + x) * 3 + c];
                const double actual = image.pixels[(std::size_t(h - 1 - y) * w + x) * 3 + c];
                const double diff = std::isfinite(actual) ? std::abs(actual - expected) : 1e30;
                max_ = std::max(max_, diff);
                sum_ += diff;
                ++values_;
                if (quantize_level(actual, bits) != quantize_level(expected, bits)) same = false;
            }
            if (same) ++same_;
        }
    }
}

ErrorStats ErrorAccumulator::result() const {
    ErrorStats stats;
    stats.max_abs = max_;
    stats.mean_abs = values_ ? sum_ / double(values_) : 0.0;
    stats.same_level_share = pixels_ ? double(same_) / double(pixels_) : 0.0;
    stats.interior_pixels = pixels_;
    stats.nonfinite = nonfinite_;
    return stats;
}

}  // namespace m3055::bench
