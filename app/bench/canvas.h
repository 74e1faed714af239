// A tiny rasterizer into an Rgb8Image for the benchmark plot: lines, dots,
// rectangles and 5 x 7 bitmap text.
#pragma once

#include "image/image.h"

#include <string>

namespace m3055::bench {

struct Color {
    unsigned char r, g, b;
};

class Canvas {
public:
    Canvas(int width, int height, Color background);
    const Rgb8Image& image() const { return image_; }
    int width() const { return image_.width; }
    int height() const { return image_.height; }

    void pixel(int x, int y, Color c);
    void line(int x0, int y0, int x1, int y1, Color c);   // Bresenham
    void dashed_line(int x0, int y0, int x1, int y1, Color c, int dash);
    void rect(int x0, int y0, int x1, int y1, Color c);   // outline, inclusive
    void fill_rect(int x0, int y0, int x1, int y1, Color c);
    void disc(int cx, int cy, int radius, Color c);
    void ring(int cx, int cy, int radius, Color c);
    // Text with its top-left corner at (x, y); each font dot is scale x scale pixels.
    void text(int x, int y, const std::string& s, Color c, int scale = 1);
    // Text turned 90 degrees counter-clockwise (reads bottom to top), starting at (x, y) going up.
    void text_up(int x, int y, const std::string& s, Color c, int scale = 1);
    static int text_width(const std::string& s, int scale = 1) { return int(s.size()) * 6 * scale - scale; }
    static int text_height(int scale = 1) { return 7 * scale; }

private:
    Rgb8Image image_;
};

}  // namespace m3055::bench
