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

// level = clamp(floor(v * (2^bits - 1) + offset), 0, 2^bits - 1), v = c clamped
// to [0, 1], sRGB-encoded first when `srgb` (the display's view transform);
// `offset` 0.5 rounds, a dithered display's is bayer4's threshold.
inline int quantize_level(double c, int bits, bool srgb = false, double offset = 0.5) {
    const double max_level = double((1 << bits) - 1);
    if (!(c > 0.0)) c = 0.0;  // also maps NaN to 0
    if (c > 1.0) c = 1.0;
    if (srgb) c = srgb_encode(c);
    const double level = std::floor(c * max_level + offset);
    return int(std::clamp(level, 0.0, max_level));
}

// The ordered 4x4 Bayer threshold in (0, 1) at pixel (x, y), counted from the
// image's BOTTOM left (GL's window coordinates): rows 0 8 2 10 / 12 4 14 6 /
// 3 11 1 9 / 15 7 13 5, each (m + 0.5) / 16.
inline double bayer4(int x, int y) {
    const int d = x ^ y;
    const int m = ((d & 1) << 3) | ((y & 1) << 2) | (d & 2) | ((y >> 1) & 1);
    return (double(m) + 0.5) / 16.0;
}

// png = round(level * 255 / (2^bits - 1)).
inline std::uint8_t level_to_png(int level, int bits) {
    const int max_level = (1 << bits) - 1;
    return std::uint8_t(std::lround(double(level) * 255.0 / double(max_level)));
}

}  // namespace m3055
