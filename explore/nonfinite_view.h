// Non-finite pixels in the explorer: a .brdf material can
// make NaN or infinite values, which the display's quantization turns into
// some level or other, so the picture alone never shows them. After a render
// of a scene that can hold them (analysis/nonfinite.h: may_render_nonfinite),
// the explorer counts them from A's raw readback, shows one warning line over
// the display, and its probe marks such a pixel (PixelProbe::text).
#pragma once

#include "analysis/nonfinite.h"
#include "image/image.h"

#include <cstdint>
#include <string>
#include <vector>

namespace m3055::explore {

struct NonFiniteView {
    NonFinite counts;
    int width = 0, height = 0;
    // One byte a display pixel, rows top to bottom like the display: 1 where
    // a channel is NaN or infinite. Empty when counts.pixels == 0.
    std::vector<std::uint8_t> marked;
    bool is_marked(int x, int y) const {
        return !marked.empty() && x >= 0 && y >= 0 && x < width && y < height &&
               marked[std::size_t(y) * std::size_t(width) + std::size_t(x)] != 0;
    }
};

// `raw` as Renderer::read_raw gives it (rows bottom to top).
NonFiniteView nonfinite_view(const RgbFloatImage& raw);

// The warning line over the display, "" when every pixel is finite:
// "Warning: 141039 pixels are NaN (the material's values there are not
// numbers; the display shows some level for them). Hover to probe them."
std::string nonfinite_warning(const NonFinite& counts);

}  // namespace m3055::explore
