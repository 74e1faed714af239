#include "grading/diff_image.h"

#include "grading/legend_font.h"
#include "grading/tiny_font.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <memory>
#include <string>
#include <mutex>
#include <vector>

namespace m3055::grading {

namespace {

// 1, 2, 3, 4-7, 8+ levels off: blue, green, yellow, orange, red: ordered by
// alarm, and told apart by lightness too (readable printed in grey).
constexpr std::uint8_t kPalette[5][3] = {
    {40, 110, 255}, {0, 200, 60}, {255, 230, 0}, {255, 140, 0}, {230, 0, 0}};
constexpr const char* kLabels[kDiffClasses] = {"0", "1", "2", "3", "4-7", "8+"};

int diff_class(int off) {
    if (off <= 3) return off;
    return off <= 7 ? 4 : 5;
}

// A quarter of A's brightness in grey: context, never mistaken for a colour class.
std::uint8_t dimmed(int bits, int r, int g, int b) {
    const int top = (1 << bits) - 1;
    const double luma = (0.2126 * r + 0.7152 * g + 0.0722 * b) / top;
    return std::uint8_t(20 + luma * 60.0);
}

// dimmed() of every colour at `bits` <= kMaxTableBits, made once a depth
// (grading makes a difference image a student, on writer threads): most
// pixels of a difference image are dimmed ones.
constexpr int kMaxTableBits = 6;
const std::vector<std::uint8_t>& dimmed_table(int bits) {
    static std::once_flag made[kMaxTableBits + 1];
    static std::vector<std::uint8_t> tables[kMaxTableBits + 1];
    std::call_once(made[bits], [bits]() {
        const int n = 1 << bits;
        std::vector<std::uint8_t>& t = tables[bits];
        t.resize(std::size_t(n) * std::size_t(n) * std::size_t(n));
        for (int r = 0; r < n; ++r)
            for (int g = 0; g < n; ++g)
                for (int b = 0; b < n; ++b) t[std::size_t((r * n + g) * n + b)] = dimmed(bits, r, g, b);
    });
    return tables[bits];
}

// A pixel's levels `l` (of A) dimmed, with the table when there is one.
struct Dimmer {
    int bits;
    const std::uint8_t* table;
    std::uint8_t operator()(const std::uint8_t* l) const {
        if (table) return table[(std::size_t(l[0]) << (2 * bits)) | (std::size_t(l[1]) << bits) | l[2]];
        return dimmed(bits, l[0], l[1], l[2]);
    }
};

// One row of the difference image. Plain pointers: the stores would
// otherwise make the compiler reload the images' buffers every pixel.
void difference_row(const std::uint8_t* la, const std::uint8_t* lb, std::uint8_t* out, int width, const Dimmer& dim) {
    for (int x = 0; x < width; ++x, la += 3, lb += 3, out += 3) {
        if (la[0] == lb[0] && la[1] == lb[1] && la[2] == lb[2]) {
            out[0] = out[1] = out[2] = dim(la);
            continue;
        }
        int off = 0;
        for (int c = 0; c < 3; ++c) off = std::max(off, std::abs(int(la[c]) - int(lb[c])));
        diff_colour(off, out);
    }
}

// The legend's layout: "levels off:", then a swatch and its label a class.
// With the real font (legend_font.h) at kLegendTextHeight pixels, readable
// where the report and a feedback page show the image at half size; the
// 3 x 5 glyphs at scale 2 only when the font file is missing.
constexpr float kLegendTextHeight = 25.0f;
constexpr int kSwatch = 20, kGap = 5, kSpace = 12;
constexpr const char* kTitle = "levels off:";

struct LegendText {
    const LegendFont* font = LegendFont::get();
    int width(const std::string& text) const {
        return font ? font->width(text, kLegendTextHeight) : text_width(upper(text), 2);
    }
    void draw(Rgb8Image& image, int x, int top, const std::string& text, const std::uint8_t rgb[3]) const {
        if (font) font->draw(image, x, top + (kLegendHeight - int(kLegendTextHeight)) / 2, text, kLegendTextHeight, rgb);
        else draw_text(image, x, top + (kLegendHeight - 10) / 2, upper(text), 2, rgb);
    }
    static std::string upper(std::string text) {
        for (char& c : text) c = char(std::toupper((unsigned char)c));
        return text;
    }
};

int legend_width() {
    const LegendText text;
    int width = 4 + text.width(kTitle) + kSpace;
    for (const char* label : kLabels) width += kSwatch + kGap + text.width(label) + kSpace;
    return width - kSpace + 4;
}

Rgb8Image make_legend(int image_width) {
    const LegendText text;
    Rgb8Image band;
    band.width = image_width;
    band.height = kLegendHeight;
    band.pixels.assign(std::size_t(band.width) * std::size_t(band.height) * 3, 0);
    const std::uint8_t white[3] = {255, 255, 255};
    text.draw(band, 4, 0, kTitle, white);
    int x = 4 + text.width(kTitle) + kSpace;
    const int swatch_top = (kLegendHeight - kSwatch) / 2;
    for (int k = 0; k < kDiffClasses; ++k) {
        std::uint8_t rgb[3] = {50, 50, 50};
        if (k > 0) std::copy_n(kPalette[k - 1], 3, rgb);
        for (int y = swatch_top; y < swatch_top + kSwatch; ++y)
            for (int dx = 0; dx < kSwatch && x + dx < band.width; ++dx)
                std::copy_n(rgb, 3, &band.pixels[(std::size_t(y) * std::size_t(band.width) + std::size_t(x + dx)) * 3]);
        text.draw(band, x + kSwatch + kGap, 0, kLabels[k], white);
        x += kSwatch + kGap + text.width(kLabels[k]) + kSpace;
    }
    return band;
}

// The legend band of an image `width` wide, drawn once a width: grading makes
// a difference image a student, and rasterizing the text each time would
// cost more than the picture.
const Rgb8Image& legend_band(int width) {
    static std::mutex mutex;
    static std::map<int, std::unique_ptr<Rgb8Image>> bands;
    const std::lock_guard<std::mutex> lock(mutex);
    std::unique_ptr<Rgb8Image>& band = bands[width];
    if (!band) band = std::make_unique<Rgb8Image>(make_legend(width));
    return *band;
}

}  // namespace

void diff_colour(int off, std::uint8_t rgb[3]) {
    if (off <= 0) {
        rgb[0] = rgb[1] = rgb[2] = 50;
        return;
    }
    std::copy_n(kPalette[diff_class(off) - 1], 3, rgb);
}

Rgb8Image difference_image(const LevelImage& a, const LevelImage& b) {
    check_comparable(a, b);
    // An image narrower than the legend is enlarged by a whole factor (each pixel a block,
    // up to 8 x 8), so that a 64 x 40 difference is not a speck beside its legend.
    constexpr int kMostEnlarged = 8;
    const int legend = legend_width();
    const int scale = a.width > 0 ? std::clamp(legend / a.width, 1, kMostEnlarged) : 1;
    Rgb8Image image;
    image.width = std::max(a.width * scale, legend);
    image.height = a.height * scale + kLegendHeight;
    image.pixels.assign(std::size_t(image.width) * std::size_t(image.height) * 3, 0);
    const Dimmer dim{a.bits, a.bits >= 1 && a.bits <= kMaxTableBits ? dimmed_table(a.bits).data() : nullptr};
    const std::size_t in_row = std::size_t(a.width) * 3, out_row = std::size_t(image.width) * 3;
    std::vector<std::uint8_t> row(in_row);
    for (int y = 0; y < a.height; ++y) {
        difference_row(a.levels.data() + std::size_t(y) * in_row, b.levels.data() + std::size_t(y) * in_row,
                       row.data(), a.width, dim);
        std::uint8_t* out = image.pixels.data() + std::size_t(y) * std::size_t(scale) * out_row;
        for (int x = 0; x < a.width; ++x)
            for (int k = 0; k < scale; ++k) std::copy_n(&row[std::size_t(x) * 3], 3, out + (std::size_t(x) * scale + k) * 3);
        for (int k = 1; k < scale; ++k) std::copy_n(out, out_row, out + std::size_t(k) * out_row);
    }
    const Rgb8Image& band = legend_band(image.width);
    std::copy(band.pixels.begin(), band.pixels.end(),
              image.pixels.begin() + std::ptrdiff_t(a.height) * scale * std::ptrdiff_t(out_row));
    return image;
}

}  // namespace m3055::grading
