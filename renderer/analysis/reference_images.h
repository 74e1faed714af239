// The CPU reference's image as the files a render writes (`m3055 render
// --reference`): the display's levels as the quantize pass makes them from the
// GPU's colour (bits, view transform, dither: image/quantize.h, its twin), and
// the linear colour for the PFM.
#pragma once

#include "image/image.h"
#include "reference/reference.h"
#include "scene/scene.h"

namespace m3055 {

// The display's PNG pixels of the reference's colour (rows top to bottom).
Rgb8Image reference_display(const ref::ReferenceImage& image, const Display& display);

// The reference's colour in float, rows bottom to top (the PFM's order, as read_raw).
RgbFloatImage reference_raw(const ref::ReferenceImage& image);

}  // namespace m3055
