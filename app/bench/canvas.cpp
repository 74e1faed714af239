#include "canvas.h"

#include "font5x7.h"

#include <cstdlib>

namespace m3055::bench {

Canvas::Canvas(int width, int height, Color background) {
    image_.width = width, image_.height = height;
    image_.pixels.resize(std::size_t(width) * height * 3);
    for (std::size_t i = 0; i < image_.pixels.size(); i += 3) {
        image_.pixels[i] = background.r, image_.pixels[i + 1] = background.g, image_.pixels[i + 2] = background.b;
    }
}

void Canvas::pixel(int x, int y, Color c) {
    if (x < 0 || y < 0 || x >= image_.width || y >= image_.height) return;
    unsigned char* p = &image_.pixels[(std::size_t(y) * image_.width + x) * 3];
    p[0] = c.r, p[1] = c.g, p[2] = c.b;
}

void Canvas::line(int x0, int y0, int x1, int y1, Color c) { dashed_line(x0, y0, x1, y1, c, 0); }

void Canvas::dashed_line(int x0, int y0, int x1, int y1, Color c, int dash) {
    const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
    const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
    int error = dx + dy, step = 0;
    for (;;) {
        if (dash <= 0 || (step / dash) % 2 == 0) pixel(x0, y0, c);
        ++step;
        if (x0 == x1 && y0 == y1) return;
        const int e2 = 2 * error;
        if (e2 >= dy) error += dy, x0 += sx;
        if (e2 <= dx) error += dx, y0 += sy;
    }
}

void Canvas::rect(int x0, int y0, int x1, int y1, Color c) {
    line(x0, y0, x1, y0, c), line(x1, y0, x1, y1, c), line(x1, y1, x0, y1, c), line(x0, y1, x0, y0, c);
}

void Canvas::fill_rect(int x0, int y0, int x1, int y1, Color c) {
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) pixel(x, y, c);
}

void Canvas::disc(int cx, int cy, int radius, Color c) {
    for (int y = -radius; y <= radius; ++y)
        for (int x = -radius; x <= radius; ++x)
            if (x * x + y * y <= radius * radius + radius) pixel(cx + x, cy + y, c);
}

void Canvas::ring(int cx, int cy, int radius, Color c) {
    for (int y = -radius; y <= radius; ++y)
        for (int x = -radius; x <= radius; ++x) {
            const int d = x * x + y * y;
            if (d <= radius * radius + radius && d >= (radius - 1) * (radius - 1) - (radius - 1))
                pixel(cx + x, cy + y, c);
        }
}

void Canvas::text(int x, int y, const std::string& s, Color c, int scale) {
    for (std::size_t i = 0; i < s.size(); ++i) {
        const std::uint8_t* columns = glyph5x7(s[i]);
        for (int col = 0; col < 5; ++col)
            for (int row = 0; row < 7; ++row)
                if (columns[col] >> row & 1)
                    fill_rect(x + (int(i) * 6 + col) * scale, y + row * scale, x + (int(i) * 6 + col) * scale + scale - 1,
                              y + row * scale + scale - 1, c);
    }
}

void Canvas::text_up(int x, int y, const std::string& s, Color c, int scale) {
    // Glyph column `col` of character i lands on row y - (i*6 + col); glyph row `row` on column x + row.
    for (std::size_t i = 0; i < s.size(); ++i) {
        const std::uint8_t* columns = glyph5x7(s[i]);
        for (int col = 0; col < 5; ++col)
            for (int row = 0; row < 7; ++row)
                if (columns[col] >> row & 1) {
                    const int px = x + row * scale, py = y - (int(i) * 6 + col) * scale;
                    fill_rect(px, py - scale + 1, px + scale - 1, py, c);
                }
    }
}

}  // namespace m3055::bench
