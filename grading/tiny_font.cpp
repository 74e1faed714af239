#include "grading/tiny_font.h"

namespace m3055::grading {

namespace {

// Each glyph: 5 rows of 3 bits, most significant bit the left column.
struct Glyph {
    char c;
    std::uint8_t rows[5];
};
constexpr Glyph kGlyphs[] = {
    {'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}}, {'3', {7, 1, 7, 1, 7}},
    {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}}, {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 1, 1, 1}},
    {'8', {7, 5, 7, 5, 7}}, {'9', {7, 5, 7, 1, 7}}, {'+', {0, 2, 7, 2, 0}}, {'-', {0, 0, 7, 0, 0}},
    {':', {0, 2, 0, 2, 0}}, {'L', {4, 4, 4, 4, 7}}, {'E', {7, 4, 6, 4, 7}}, {'V', {5, 5, 5, 5, 2}},
    {'S', {7, 4, 7, 1, 7}}, {'O', {7, 5, 5, 5, 7}}, {'F', {7, 4, 6, 4, 4}},
};

const Glyph* find_glyph(char c) {
    for (const Glyph& glyph : kGlyphs)
        if (glyph.c == c) return &glyph;
    return nullptr;
}

void put(Rgb8Image& image, int x, int y, const std::uint8_t rgb[3]) {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
    std::uint8_t* p = &image.pixels[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 3];
    p[0] = rgb[0];
    p[1] = rgb[1];
    p[2] = rgb[2];
}

}  // namespace

int text_width(const std::string& text, int scale) { return int(text.size()) * 4 * scale; }

void draw_text(Rgb8Image& image, int x, int y, const std::string& text, int scale, const std::uint8_t rgb[3]) {
    for (std::size_t i = 0; i < text.size(); ++i) {
        const Glyph* glyph = find_glyph(text[i]);
        if (!glyph) continue;
        const int left = x + int(i) * 4 * scale;
        for (int row = 0; row < 5; ++row)
            for (int col = 0; col < 3; ++col)
                if (glyph->rows[row] & (4 >> col))
                    for (int dy = 0; dy < scale; ++dy)
                        for (int dx = 0; dx < scale; ++dx) put(image, left + col * scale + dx, y + row * scale + dy, rgb);
    }
}

}  // namespace m3055::grading
