// PNG via stb (the Debian libstb build; no STB_*_IMPLEMENTATION here).
#include "image/image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cstring>
#include <memory>

namespace m3055 {
namespace {

void append_bytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

bool has_consistent_size(const Rgb8Image& image) {
    return image.width > 0 && image.height > 0 &&
           image.pixels.size() == std::size_t(image.width) * std::size_t(image.height) * 3;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Rgb8Image& image) {
    if (!has_consistent_size(image))
        throw ImageError("encode_png: pixel buffer does not match " + std::to_string(image.width) +
                         "x" + std::to_string(image.height) + " RGB");
    // stb's PNG writer has no timestamps or other varying chunks: the same
    // pixels always give the same bytes (the screenshot checks rely on it).
    std::vector<std::uint8_t> out;
    const int ok = stbi_write_png_to_func(append_bytes, &out, image.width, image.height, 3,
                                          image.pixels.data(), image.width * 3);
    if (!ok) throw ImageError("encode_png: stb_image_write failed");
    return out;
}

void write_png(const std::string& path, const Rgb8Image& image) {
    std::vector<std::uint8_t> bytes;
    try {
        bytes = encode_png(image);
    } catch (const ImageError& e) {
        throw ImageError(path + ": " + e.what());
    }
    write_file_atomic(path, bytes.data(), bytes.size());
}

Rgb8Image read_png(const std::string& path) {
    int width = 0, height = 0, channels_in_file = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> data(
        stbi_load(path.c_str(), &width, &height, &channels_in_file, 3), stbi_image_free);
    if (!data) {
        const char* reason = stbi_failure_reason();
        throw ImageError(path + ": cannot read PNG: " + (reason ? reason : "unknown error"));
    }
    Rgb8Image image;
    image.width = width;
    image.height = height;
    image.pixels.assign(data.get(), data.get() + std::size_t(width) * std::size_t(height) * 3);
    return image;
}

}  // namespace m3055
