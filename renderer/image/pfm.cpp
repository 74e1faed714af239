// PFM (portable float map): "PF\n<w> <h>\n<scale>\n" then float32 RGB triples,
// rows bottom to top. A negative scale means little-endian data.
#include "image/image.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

namespace m3055 {
namespace {

bool host_is_little_endian() {
    const std::uint16_t one = 1;
    std::uint8_t first = 0;
    std::memcpy(&first, &one, 1);
    return first == 1;
}

float byte_swapped(float value) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &value, 4);
    bits = (bits >> 24) | ((bits >> 8) & 0xff00u) | ((bits << 8) & 0xff0000u) | (bits << 24);
    std::memcpy(&value, &bits, 4);
    return value;
}

bool is_space(std::uint8_t c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

// Reads the header's whitespace-separated tokens from a byte buffer.
class HeaderReader {
public:
    HeaderReader(const std::vector<std::uint8_t>& bytes, std::string path)
        : bytes_(bytes), path_(std::move(path)) {}

    [[noreturn]] void reject(const std::string& why) const {
        throw ImageError(path_ + ": not a PFM file: " + why);
    }

    std::string token(const char* what) {
        while (pos_ < bytes_.size() && is_space(bytes_[pos_])) ++pos_;
        const std::size_t start = pos_;
        while (pos_ < bytes_.size() && !is_space(bytes_[pos_]) && pos_ - start < 64) ++pos_;
        if (pos_ == start) reject(std::string("missing ") + what);
        return std::string(bytes_.begin() + long(start), bytes_.begin() + long(pos_));
    }

    int dimension(const char* what) {
        const std::string text = token(what);
        long value = 0;
        for (const char c : text) {
            if (c < '0' || c > '9' || value > 1000000) reject(std::string("bad ") + what + " '" + text + "'");
            value = value * 10 + (c - '0');
        }
        if (value < 1 || value > 1000000) reject(std::string("bad ") + what + " '" + text + "'");
        return int(value);
    }

    double scale() {
        const std::string text = token("scale");
        errno = 0;
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (errno != 0 || end != text.c_str() + text.size() || !std::isfinite(value) || value == 0.0)
            reject("bad scale '" + text + "'");
        return value;
    }

    // Exactly one whitespace byte separates the scale from the raster.
    std::size_t raster_start() {
        if (pos_ >= bytes_.size() || !is_space(bytes_[pos_])) reject("no newline after the scale");
        return pos_ + 1;
    }

private:
    const std::vector<std::uint8_t>& bytes_;
    std::string path_;
    std::size_t pos_ = 0;
};

std::vector<std::uint8_t> read_all(const io::InputPath& file) {
    std::ifstream in(file.path, std::ios::binary);
    if (!in) throw ImageError(file.shown + ": cannot open: " + std::strerror(errno));
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw ImageError(file.shown + ": cannot read: " + std::strerror(errno));
    return bytes;
}

// "PF\n<w> <h>\n-1.0\n" (little-endian data), after checking the buffer's size.
std::string pfm_header(const RgbFloatImage& image) {
    const std::size_t count = std::size_t(image.width) * std::size_t(image.height) * 3;
    if (image.width <= 0 || image.height <= 0 || image.pixels.size() != count)
        throw ImageError("encode_pfm: pixel buffer does not match " + std::to_string(image.width) +
                         "x" + std::to_string(image.height) + " RGB");
    return "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
}

}  // namespace

std::vector<std::uint8_t> encode_pfm(const RgbFloatImage& image) {
    const std::string header = pfm_header(image);
    const std::size_t count = image.pixels.size();
    std::vector<std::uint8_t> out(header.begin(), header.end());
    out.resize(header.size() + count * 4);
    // Rows are already bottom to top (as PFM wants); only byte order may need work.
    std::uint8_t* dst = out.data() + header.size();
    if (host_is_little_endian()) {
        std::memcpy(dst, image.pixels.data(), count * 4);
    } else {
        for (std::size_t i = 0; i < count; ++i) {
            const float swapped = byte_swapped(image.pixels[i]);
            std::memcpy(dst + 4 * i, &swapped, 4);
        }
    }
    return out;
}

FileContents pfm_file(const std::string& path, const RgbFloatImage& image) {
    if (!host_is_little_endian()) return {path, encode_pfm(image)};
    const std::string header = pfm_header(image);
    FileContents file{path, std::vector<std::uint8_t>(header.begin(), header.end())};
    file.more = image.pixels.data();
    file.more_size = image.pixels.size() * sizeof(float);
    return file;
}

void write_pfm(const std::string& path, const RgbFloatImage& image) {
    std::vector<std::uint8_t> bytes;
    try {
        bytes = encode_pfm(image);
    } catch (const ImageError& e) {
        throw ImageError(path + ": " + e.what());
    }
    write_file_atomic(path, bytes.data(), bytes.size());
}

RgbFloatImage read_pfm(const std::string& path) { return read_pfm(io::InputPath::as_given(path)); }

RgbFloatImage read_pfm(const io::InputPath& file) {
    const std::vector<std::uint8_t> bytes = read_all(file);
    HeaderReader header(bytes, file.shown);
    const std::string magic = header.token("magic");
    if (magic != "PF" && magic != "Pf") header.reject("magic is '" + magic.substr(0, 8) + "', not PF or Pf");
    const int channels = magic == "PF" ? 3 : 1;
    const int width = header.dimension("width");
    const int height = header.dimension("height");
    const bool file_little_endian = header.scale() < 0.0;
    const std::size_t start = header.raster_start();

    const std::size_t values = std::size_t(width) * std::size_t(height) * std::size_t(channels);
    const std::size_t have = bytes.size() - start;
    if (have != values * 4)
        header.reject("raster has " + std::to_string(have) + " bytes, expected " + std::to_string(values * 4));

    RgbFloatImage image;
    image.width = width;
    image.height = height;
    image.pixels.resize(std::size_t(width) * std::size_t(height) * 3);
    const bool swap = file_little_endian != host_is_little_endian();
    for (std::size_t i = 0; i < values; ++i) {
        float value = 0.0f;
        std::memcpy(&value, bytes.data() + start + 4 * i, 4);
        if (swap) value = byte_swapped(value);
        if (channels == 3) {
            image.pixels[i] = value;
        } else {  // greyscale "Pf": the same value in R, G and B
            image.pixels[3 * i] = image.pixels[3 * i + 1] = image.pixels[3 * i + 2] = value;
        }
    }
    return image;
}

}  // namespace m3055
