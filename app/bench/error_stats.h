// Error of a rendered (unquantized) image against the double-precision CPU
// reference, on interior pixels only (ref::is_interior: away from silhouettes,
// where a pixel's coverage, not its shading, decides the colour).
#pragma once

#include "image/image.h"
#include "reference/reference.h"

namespace m3055::bench {

struct ErrorStats {
    double max_abs = 0;           // max |image - reference| over interior pixels and channels
    double mean_abs = 0;          // mean of the same
    double same_level_share = 0;  // share of interior pixels whose display levels (all channels) match
    long interior_pixels = 0;
    long nonfinite = 0;           // NaN or Inf values in the image
    bool valid() const { return interior_pixels > 0; }
};

// Accumulates over several images (several scenes of one "way").
class ErrorAccumulator {
public:
    // `image` rows bottom to top (GL readback), `reference` rows top to bottom.
    void add(const RgbFloatImage& image, const ref::ReferenceImage& reference, int bits);
    ErrorStats result() const;

private:
    double max_ = 0, sum_ = 0;
    long values_ = 0, pixels_ = 0, same_ = 0, nonfinite_ = 0;
};

}  // namespace m3055::bench
