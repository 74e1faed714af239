#include "explore/nonfinite_view.h"

#include <cmath>

namespace m3055::explore {

NonFiniteView nonfinite_view(const RgbFloatImage& raw) {
    NonFiniteView view;
    view.counts = count_nonfinite(raw);
    view.width = raw.width;
    view.height = raw.height;
    if (view.counts.pixels == 0) return view;
    view.marked.assign(std::size_t(raw.width) * std::size_t(raw.height), 0);
    for (int y = 0; y < raw.height; ++y) {
        const float* p = raw.pixels.data() + std::size_t(y) * std::size_t(raw.width) * 3;
        std::uint8_t* row = view.marked.data() + std::size_t(raw.height - 1 - y) * std::size_t(raw.width);
        for (int x = 0; x < raw.width; ++x, p += 3)
            row[x] = std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) ? 0 : 1;
    }
    return view;
}

std::string nonfinite_warning(const NonFinite& counts) {
    if (counts.pixels == 0) return "";
    return "Warning: " + nonfinite_text(counts) +
           " (the material's values there are not numbers; the display shows some level for them). "
           "Hover to probe them.";
}

}  // namespace m3055::explore
