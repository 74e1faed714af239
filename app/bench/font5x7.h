// A 5 x 7 bitmap font for printable ASCII, for the benchmark plot (stb has no
// font rasterizer, and the plot must be drawn by the project itself).
#pragma once

#include <cstdint>

namespace m3055::bench {

// Five column bytes for `c` (bit 0 = top row); a box for characters outside 32..126.
const std::uint8_t* glyph5x7(char c);

}  // namespace m3055::bench
