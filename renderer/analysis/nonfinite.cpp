#include "analysis/nonfinite.h"

#include "brdf_file/brdf_model.h"

#include <cmath>

namespace m3055 {

NonFinite count_nonfinite(const RgbFloatImage& raw) {
    NonFinite out;
    const float* p = raw.pixels.data();
    const std::size_t n = raw.pixels.size() / 3;
    for (std::size_t i = 0; i < n; ++i, p += 3) {
        // One test for the common case: the sum of finite values is finite
        // unless it overflows, which the exact test below sorts out.
        if (std::isfinite(p[0] + p[1] + p[2]) || (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
            continue;
        ++out.pixels;
        if (std::isnan(p[0]) || std::isnan(p[1]) || std::isnan(p[2])) ++out.nan;
        else ++out.inf;
    }
    return out;
}

bool may_render_nonfinite(const Scene& scene) {
    for (const Object& object : scene.objects)
        if (find_brdf_model(object.material.model())) return true;
    return false;
}

std::string nonfinite_text(const NonFinite& c) {
    if (c.pixels == 0) return "";
    const std::string count = std::to_string(c.pixels) + (c.pixels == 1 ? " pixel is " : " pixels are ");
    if (c.inf == 0) return count + "NaN";
    if (c.nan == 0) return count + "infinite";
    return count + "not finite (" + std::to_string(c.nan) + " NaN, " + std::to_string(c.inf) + " infinite)";
}

}  // namespace m3055
