// PNG: written with zlib (fast, deterministic), read with stb (the Debian
// libstb build; no STB_*_IMPLEMENTATION here).
#include "image/image.h"

#include <stb_image.h>
#include <zlib.h>

#include <cstring>
#include <memory>

namespace m3055 {
namespace {

bool has_consistent_size(const Rgb8Image& image) {
    return image.width > 0 && image.height > 0 &&
           image.pixels.size() == std::size_t(image.width) * std::size_t(image.height) * 3;
}

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(std::uint8_t(value >> shift));
}

// One chunk: length, type, data, CRC of type + data (PNG spec section 5.3).
void put_chunk(std::vector<std::uint8_t>& out, const char type[4], const std::uint8_t* data, std::size_t size) {
    put_u32(out, std::uint32_t(size));
    const std::size_t start = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data, data + size);
    put_u32(out, std::uint32_t(crc32(0L, out.data() + start, uInt(size + 4))));
}

// Scanlines with the "up" filter (type 2: each byte minus the one above).
// The display's images are large flat areas and smooth vertical gradations,
// which "up" turns into runs of zeros that run-length deflate packs tightly.
// PNG filter 2 (Up) of row `y` into `out` (stride + 1 bytes, the filter type first).
void filter_row(const Rgb8Image& image, int y, std::uint8_t* out) {
    const std::size_t stride = std::size_t(image.width) * 3;
    const std::uint8_t* row = &image.pixels[std::size_t(y) * stride];
    const std::uint8_t* above = y > 0 ? row - stride : nullptr;
    out[0] = 2;
    for (std::size_t i = 0; i < stride; ++i) out[i + 1] = std::uint8_t(row[i] - (above ? above[i] : 0));
}

// The filtered scanlines, deflated one row at a time: neither the filtered
// image nor a worst-case output buffer (each as large as the image, 192 MiB at
// 8192 x 8192) is held. Feeding deflate in pieces without flushing gives the
// same stream as feeding it all at once.
std::vector<std::uint8_t> deflate_rows(const Rgb8Image& image) {
    // Z_RLE at level 1: several times faster than stb's encoder, and smaller on
    // these images. Deterministic for a given zlib version.
    z_stream stream{};
    if (deflateInit2(&stream, 1, Z_DEFLATED, 15, 8, Z_RLE) != Z_OK) throw ImageError("encode_png: deflateInit2 failed");
    std::vector<std::uint8_t> row(std::size_t(image.width) * 3 + 1), out;
    std::uint8_t buffer[1 << 16];
    int status = Z_OK;
    for (int y = 0; y < image.height && status != Z_STREAM_ERROR; ++y) {
        filter_row(image, y, row.data());
        stream.next_in = row.data();
        stream.avail_in = uInt(row.size());
        const int flush = y + 1 == image.height ? Z_FINISH : Z_NO_FLUSH;
        do {
            stream.next_out = buffer;
            stream.avail_out = uInt(sizeof buffer);
            status = deflate(&stream, flush);
            out.insert(out.end(), buffer, buffer + (sizeof buffer - stream.avail_out));
        } while (status == Z_OK && (stream.avail_out == 0 || flush == Z_FINISH));
    }
    deflateEnd(&stream);
    if (status != Z_STREAM_END) throw ImageError("encode_png: deflate failed");
    return out;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Rgb8Image& image) {
    if (!has_consistent_size(image))
        throw ImageError("encode_png: pixel buffer does not match " + std::to_string(image.width) +
                         "x" + std::to_string(image.height) + " RGB");
    // No timestamps or other varying chunks: the same pixels always give the
    // same bytes (the explorer's screenshot and batch rely on it).
    static const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    std::vector<std::uint8_t> out(signature, signature + 8);
    std::vector<std::uint8_t> header;
    put_u32(header, std::uint32_t(image.width));
    put_u32(header, std::uint32_t(image.height));
    header.insert(header.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, adaptive filters, no interlace
    put_chunk(out, "IHDR", header.data(), header.size());
    const std::vector<std::uint8_t> compressed = deflate_rows(image);
    put_chunk(out, "IDAT", compressed.data(), compressed.size());
    put_chunk(out, "IEND", nullptr, 0);
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

Rgb8Image read_png(const std::string& path) { return read_png(io::InputPath::as_given(path)); }

Rgb8Image read_png(const io::InputPath& file) {
    int width = 0, height = 0, channels_in_file = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> data(
        stbi_load(file.path.c_str(), &width, &height, &channels_in_file, 3), stbi_image_free);
    if (!data) {
        const char* reason = stbi_failure_reason();
        throw ImageError(file.shown + ": cannot read PNG: " + (reason ? reason : "unknown error"));
    }
    Rgb8Image image;
    image.width = width;
    image.height = height;
    image.pixels.assign(data.get(), data.get() + std::size_t(width) * std::size_t(height) * 3);
    return image;
}

}  // namespace m3055
