// The false-colour difference image of `m3055 compare --diff` and of grading:
// each pixel coloured by how many display levels it is off (the largest of its
// three channels), over a dimmed grey copy of image A so the eye finds where
// the differences are; a legend band under the picture names the colours
// (in DejaVu Sans through stb_truetype: legend_font.h).
#pragma once

#include "grading/level_compare.h"
#include "image/image.h"

namespace m3055::grading {

// Legend classes, in order: 0 (A dimmed), 1, 2, 3, 4-7, 8+ levels off.
inline constexpr int kDiffClasses = 6;
// The colour of a pixel `off` levels off (off >= 1); 0 gives the dimmed A.
void diff_colour(int off, std::uint8_t rgb[3]);

// The picture with the legend band below it: A's size, or a whole multiple of it (at
// most 8) when A is narrower than the legend, and widened with black to the legend's
// width when still narrower. Throws CompareError when
// the sizes differ.
Rgb8Image difference_image(const LevelImage& a, const LevelImage& b);

// Height in pixels of the legend band under the picture.
inline constexpr int kLegendHeight = 36;

}  // namespace m3055::grading
