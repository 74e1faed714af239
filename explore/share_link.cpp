#include "explore/share_link.h"

#include "scene/load.h"

#include <nlohmann/json.hpp>
#include <zlib.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace m3055::explore {

namespace {

std::string encode(const std::string& bytes, const char* alphabet, bool pad) {
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned v = unsigned(std::uint8_t(bytes[i])) << 16 | unsigned(std::uint8_t(bytes[i + 1])) << 8 |
                           unsigned(std::uint8_t(bytes[i + 2]));
        out += alphabet[v >> 18];
        out += alphabet[(v >> 12) & 63];
        out += alphabet[(v >> 6) & 63];
        out += alphabet[v & 63];
    }
    const std::size_t rest = bytes.size() - i;
    if (rest > 0) {
        unsigned v = unsigned(std::uint8_t(bytes[i])) << 16;
        if (rest == 2) v |= unsigned(std::uint8_t(bytes[i + 1])) << 8;
        out += alphabet[v >> 18];
        out += alphabet[(v >> 12) & 63];
        if (rest == 2) out += alphabet[(v >> 6) & 63];
        if (pad) out += rest == 2 ? "=" : "==";
    }
    return out;
}

constexpr const char* kBase64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
constexpr const char* kBase64Url = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";

}  // namespace

std::string base64url_encode(const std::string& bytes) { return encode(bytes, kBase64Url, false); }

std::string base64_encode(const std::string& bytes) { return encode(bytes, kBase64, true); }

std::string base64url_decode(const std::string& text) {
    std::string out;
    unsigned bits = 0;
    int count = 0;
    for (char c : text) {
        int v;
        if (c >= 'A' && c <= 'Z') v = c - 'A';
        else if (c >= 'a' && c <= 'z') v = c - 'a' + 26;
        else if (c >= '0' && c <= '9') v = c - '0' + 52;
        else if (c == '-') v = 62;
        else if (c == '_') v = 63;
        else throw std::runtime_error("share link: not base64url (a character outside A-Z a-z 0-9 - _)");
        bits = (bits << 6) | unsigned(v);
        count += 6;
        if (count >= 8) {
            count -= 8;
            out += char((bits >> count) & 0xff);
        }
    }
    return out;
}

std::string share_token(const Scene& scene) {
    const std::string text = scene_to_json(scene).dump();
    uLongf size = compressBound(uLong(text.size()));
    std::vector<Bytef> packed(size);
    if (compress2(packed.data(), &size, reinterpret_cast<const Bytef*>(text.data()), uLong(text.size()),
                  Z_BEST_COMPRESSION) != Z_OK)
        throw std::runtime_error("share link: cannot compress the scene");
    return base64url_encode(std::string(reinterpret_cast<const char*>(packed.data()), size));
}

std::string scene_text_from_share_token(const std::string& token) {
    const std::string packed = base64url_decode(token);
    z_stream stream{};
    if (inflateInit(&stream) != Z_OK) throw std::runtime_error("share link: cannot unpack");
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(packed.data()));
    stream.avail_in = uInt(packed.size());
    std::string text;
    char chunk[16384];
    int status = Z_OK;
    while (status == Z_OK) {
        stream.next_out = reinterpret_cast<Bytef*>(chunk);
        stream.avail_out = sizeof chunk;
        status = inflate(&stream, Z_NO_FLUSH);
        text.append(chunk, sizeof chunk - stream.avail_out);
        if (text.size() > kMaxSharedSceneBytes) {
            inflateEnd(&stream);
            throw std::runtime_error("share link: the scene unpacks to more than 4 MiB");
        }
        if (status == Z_BUF_ERROR && stream.avail_in == 0) break;  // input ended before the stream did
    }
    inflateEnd(&stream);
    if (status != Z_STREAM_END) throw std::runtime_error("share link: not a whole compressed scene (cut short?)");
    return text;
}

}  // namespace m3055::explore
