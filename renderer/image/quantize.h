// docs/spec.md#2-display: the M3055's quantization, on the CPU. The GLSL post pass
// (glsl/passes/quantize.frag) computes exactly the same thing.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace m3055 {

// IEC 61966-2-1's sRGB encoding of a linear value in [0, 1] (a display's
// "sRGB" view transform, before its levels).
inline double srgb_encode(double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055; }

// level = clamp(floor(v * (2^bits - 1) + 0.5), 0, 2^bits - 1), v = c clamped
// to [0, 1], sRGB-encoded first when `srgb` (the display's view transform).
inline int quantize_level(double c, int bits, bool srgb = false) {
    const double max_level = double((1 << bits) - 1);
    if (!(c > 0.0)) c = 0.0;  // also maps NaN to 0
    if (c > 1.0) c = 1.0;
    if (srgb) c = srgb_encode(c);
    const double level = std::floor(c * max_level + 0.5);
    return int(std::clamp(level, 0.0, max_level));
}

// png = round(level * 255 / (2^bits - 1)).
inline std::uint8_t level_to_png(int level, int bits) {
    const int max_level = (1 << bits) - 1;
    return std::uint8_t(std::lround(double(level) * 255.0 / double(max_level)));
}

}  // namespace m3055
