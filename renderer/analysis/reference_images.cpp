#include "analysis/reference_images.h"

#include "image/quantize.h"

#include <cstddef>

namespace m3055 {

Rgb8Image reference_display(const ref::ReferenceImage& image, const Display& display) {
    Rgb8Image out;
    out.width = image.width;
    out.height = image.height;
    out.pixels.resize(std::size_t(image.width) * std::size_t(image.height) * 3);
    const bool srgb = display.view_transform == ViewTransform::srgb;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            // The dither's threshold at GL's pixel: rows counted from the bottom.
            const double offset = display.dither ? bayer4(x, image.height - 1 - y) : 0.5;
            const std::size_t at = (std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 3;
            for (int c = 0; c < 3; ++c)
                out.pixels[at + c] =
                    level_to_png(quantize_level(image.rgb[at + c], display.bits, srgb, offset), display.bits);
        }
    return out;
}

RgbFloatImage reference_raw(const ref::ReferenceImage& image) {
    RgbFloatImage out;
    out.width = image.width;
    out.height = image.height;
    out.pixels.resize(image.rgb.size());
    const std::size_t row = std::size_t(image.width) * 3;
    for (int y = 0; y < image.height; ++y)
        for (std::size_t i = 0; i < row; ++i)
            out.pixels[std::size_t(image.height - 1 - y) * row + i] = float(image.rgb[std::size_t(y) * row + i]);
    return out;
}

}  // namespace m3055
