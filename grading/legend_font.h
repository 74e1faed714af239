// The difference legend's text in a real font (the 3 x 5
// pixel glyphs were unreadable at the size the report shows the image):
// DejaVu Sans (fonts-dejavu-core, scripts/setup) rasterized by stb_truetype
// (libstb-dev), anti-aliased white on the legend's black band.
#pragma once

#include "image/image.h"

#include <cstdint>
#include <string>

namespace m3055::grading {

// Debian's DejaVu Sans; $M3055_LEGEND_FONT names another .ttf.
inline constexpr const char* kLegendFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

class LegendFont {
public:
    // The font, read once a process; nullptr when the file cannot be read or
    // is not a TrueType font, after one line on stderr naming the file (the
    // legend then falls back to the 3 x 5 glyphs of tiny_font.h).
    static const LegendFont* get();

    // Width in pixels of `text` (ASCII) at `pixel_height`.
    int width(const std::string& text, float pixel_height) const;
    // Draws `text` with the top of its ascent at `top`, blending `rgb` over
    // the image by the glyphs' coverage; clipped to the image.
    void draw(Rgb8Image& image, int x, int top, const std::string& text, float pixel_height,
              const std::uint8_t rgb[3]) const;

    struct Impl;
    explicit LegendFont(Impl* impl) : impl_(impl) {}

private:
    Impl* impl_;
};

// The one line get() prints when the font cannot be used.
std::string legend_font_problem(const std::string& path, const std::string& why);

}  // namespace m3055::grading
