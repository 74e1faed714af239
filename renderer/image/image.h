// Image files: PNG (8-bit RGB, stb) and PFM (float RGB), written atomically:
// to a temporary file in the same folder, then renamed over the target, so a
// failed run leaves no partial file and never destroys an existing one.
#pragma once

#include "io/input_path.h"

#include <cstdint>
#include <functional>
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
// changes under us between the two steps). `committed`, when given, runs once
// every file is in place, under the lock an interrupt waits for
// (image/temporary_files.h): what it counts is exactly what was written.
// A target that exists and is not a regular file (a FIFO, a device, a folder,
// a symbolic link) is an error; nothing is written then.
struct FileContents {
    std::string path;
    std::vector<std::uint8_t> bytes;
    // Written after `bytes` when not null, without a copy: the raw image's
    // floats (768 MiB at 8192 x 8192), which must outlive the write.
    const void* more = nullptr;
    std::size_t more_size = 0;
};
void write_files_atomic(const std::vector<FileContents>& files, const std::function<void()>& committed = {});

void write_png(const std::string& path, const Rgb8Image& image);
void write_pfm(const std::string& path, const RgbFloatImage& image);

// Encodes in memory (used for byte-identity checks and by write_*).
std::vector<std::uint8_t> encode_png(const Rgb8Image& image);
std::vector<std::uint8_t> encode_pfm(const RgbFloatImage& image);
// The PFM file for write_files_atomic, the same bytes as encode_pfm(image):
// the header, then on a little-endian host `image`'s own pixels, borrowed
// (`image` must outlive the write), not copied.
FileContents pfm_file(const std::string& path, const RgbFloatImage& image);

// Readers, for tests and tools. Throw ImageError on failure.
Rgb8Image read_png(const std::string& path);
RgbFloatImage read_pfm(const std::string& path);
// The same for a file opened at `file.path`, every message naming `file.shown`.
Rgb8Image read_png(const io::InputPath& file);
RgbFloatImage read_pfm(const io::InputPath& file);

}  // namespace m3055
