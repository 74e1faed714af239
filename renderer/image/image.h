// Image files: PNG (8-bit RGB, stb) and PFM (float RGB), written atomically:
// to a temporary file in the same folder, then renamed over the target, so a
// failed run leaves no partial file and never destroys an existing one.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace m3055 {

class ImageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// 8-bit RGB, rows top to bottom (PNG order).
struct Rgb8Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;  // width * height * 3
};

// Float RGB, rows BOTTOM to top (PFM and OpenGL readback order).
struct RgbFloatImage {
    int width = 0;
    int height = 0;
    std::vector<float> pixels;  // width * height * 3
};

// Writes `bytes` to `path` atomically. Throws ImageError("PATH: reason").
void write_file_atomic(const std::string& path, const void* bytes, std::size_t size);

// Writes several files all or nothing as far as the filesystem allows: all
// temporary files first, then the renames (which only fail if the folder
// changes under us between the two steps).
struct FileContents {
    std::string path;
    std::vector<std::uint8_t> bytes;
};
void write_files_atomic(const std::vector<FileContents>& files);

void write_png(const std::string& path, const Rgb8Image& image);
void write_pfm(const std::string& path, const RgbFloatImage& image);

// Encodes in memory (used for byte-identity checks and by write_*).
std::vector<std::uint8_t> encode_png(const Rgb8Image& image);
std::vector<std::uint8_t> encode_pfm(const RgbFloatImage& image);

// Readers, for tests and tools. Throw ImageError on failure.
Rgb8Image read_png(const std::string& path);
RgbFloatImage read_pfm(const std::string& path);

}  // namespace m3055
