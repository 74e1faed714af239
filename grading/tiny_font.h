// A 3 x 5 pixel font for the few characters the difference image's legend
// writes ("LEVELS OFF 0 1 2 3 4-7 8+"): the fallback when the legend's real
// font (legend_font.h) is missing.
#pragma once

#include "image/image.h"

#include <cstdint>
#include <string>

namespace m3055::grading {

// Draws `text` (upper case letters of the legend, digits, '+', '-', ':' and
// space; anything else as a space) with its top-left corner at (x, y), each
// font pixel `scale` x `scale` image pixels, clipped to the image.
void draw_text(Rgb8Image& image, int x, int y, const std::string& text, int scale, const std::uint8_t rgb[3]);
// The width in image pixels draw_text covers (4 font columns a character).
int text_width(const std::string& text, int scale);

}  // namespace m3055::grading
