#include "grading/legend_font.h"

#include <stb_truetype.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <iostream>
#include <iterator>
#include <mutex>
#include <vector>

namespace m3055::grading {

struct LegendFont::Impl {
    std::vector<unsigned char> bytes;  // stbtt_fontinfo points into these
    stbtt_fontinfo info{};
};

std::string legend_font_problem(const std::string& path, const std::string& why) {
    return "m3055: warning: " + path + ": " + why +
           " (the difference legend's font; Debian: apt-get install fonts-dejavu-core, or set M3055_LEGEND_FONT); "
           "the legend is drawn in 3 x 5 pixel letters";
}

const LegendFont* LegendFont::get() {
    static std::once_flag once;
    static const LegendFont* font = nullptr;
    std::call_once(once, [] {
        const char* env = std::getenv("M3055_LEGEND_FONT");
        const std::string path = env && *env ? env : kLegendFontPath;
        auto impl = std::make_unique<Impl>();
        std::ifstream in(path, std::ios::binary);
        if (in) impl->bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        if (!in && impl->bytes.empty()) {
            std::cerr << legend_font_problem(path, "cannot read the file") << "\n";
            return;
        }
        const int offset = stbtt_GetFontOffsetForIndex(impl->bytes.data(), 0);
        if (impl->bytes.size() < 12 || offset < 0 || !stbtt_InitFont(&impl->info, impl->bytes.data(), offset)) {
            std::cerr << legend_font_problem(path, "not a TrueType font") << "\n";
            return;
        }
        font = new LegendFont(impl.release());  // lives as long as the process
    });
    return font;
}

int LegendFont::width(const std::string& text, float pixel_height) const {
    const float scale = stbtt_ScaleForPixelHeight(&impl_->info, pixel_height);
    float x = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        int advance = 0, left = 0;
        stbtt_GetCodepointHMetrics(&impl_->info, (unsigned char)text[i], &advance, &left);
        x += float(advance) * scale;
        if (i + 1 < text.size())
            x += scale * float(stbtt_GetCodepointKernAdvance(&impl_->info, (unsigned char)text[i], (unsigned char)text[i + 1]));
    }
    return int(x + 0.999f);
}

void LegendFont::draw(Rgb8Image& image, int x0, int top, const std::string& text, float pixel_height,
                      const std::uint8_t rgb[3]) const {
    const float scale = stbtt_ScaleForPixelHeight(&impl_->info, pixel_height);
    int ascent = 0, descent = 0, gap = 0;
    stbtt_GetFontVMetrics(&impl_->info, &ascent, &descent, &gap);
    const int baseline = top + int(float(ascent) * scale + 0.5f);
    float x = float(x0);
    for (std::size_t i = 0; i < text.size(); ++i) {
        const int c = (unsigned char)text[i];
        int advance = 0, left = 0, w = 0, h = 0, xoff = 0, yoff = 0;
        stbtt_GetCodepointHMetrics(&impl_->info, c, &advance, &left);
        // Whole-pixel glyph origins: the same bitmap for a letter wherever it is.
        unsigned char* bitmap = stbtt_GetCodepointBitmap(&impl_->info, scale, scale, c, &w, &h, &xoff, &yoff);
        const int gx = int(x + 0.5f) + xoff, gy = baseline + yoff;
        for (int y = 0; y < h; ++y) {
            if (gy + y < 0 || gy + y >= image.height) continue;
            for (int dx = 0; dx < w; ++dx) {
                if (gx + dx < 0 || gx + dx >= image.width) continue;
                const int a = bitmap[y * w + dx];
                if (a == 0) continue;
                std::uint8_t* p = &image.pixels[(std::size_t(gy + y) * std::size_t(image.width) + std::size_t(gx + dx)) * 3];
                for (int k = 0; k < 3; ++k) p[k] = std::uint8_t((rgb[k] * a + p[k] * (255 - a) + 127) / 255);
            }
        }
        stbtt_FreeBitmap(bitmap, nullptr);
        x += float(advance) * scale;
        if (i + 1 < text.size())
            x += scale * float(stbtt_GetCodepointKernAdvance(&impl_->info, c, (unsigned char)text[i + 1]));
    }
}

}  // namespace m3055::grading
