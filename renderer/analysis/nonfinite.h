// Pixels of a render that are not finite numbers: any .brdf
// material can make NaN or infinite values, which the display's quantization
// turns into some level or other; grading fails the image check on them,
// the explorer warns and its probe marks them, and
// `render` and `batch` warn.
#pragma once

#include "image/image.h"
#include "scene/scene.h"

#include <cstddef>
#include <string>

namespace m3055 {

struct NonFinite {
    std::size_t pixels = 0;  // pixels with a channel NaN or infinite
    std::size_t nan = 0;     // of them, those with a NaN channel
    std::size_t inf = 0;     // the others: an infinite channel, none NaN
};

NonFinite count_nonfinite(const RgbFloatImage& raw);

// Whether a render of `scene` can hold non-finite pixels worth a raw readback:
// an object's material comes from a .brdf file. The built-in models' values
// are finite over their loader-checked ranges (tests/stress_test.cpp,
// tests/classic_stress_test.cpp), so grade and batch read the raw image back
// only for these scenes (15-20 % of grading's time for every scene otherwise).
bool may_render_nonfinite(const Scene& scene);

// "141039 pixels are NaN", "1 pixel is infinite", "3 pixels are not finite
// (2 NaN, 1 infinite)"; "" when none.
std::string nonfinite_text(const NonFinite& counts);

}  // namespace m3055
