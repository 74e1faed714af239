#include "explore/share_link.h"

#include "io/input_file.h"
#include "scene/load.h"

#include <nlohmann/json.hpp>
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
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

namespace {

using nlohmann::json;

// A bundle's file name: relative, "/"-separated, each part a plain name.
bool plain_relative_name(const std::string& name) {
    if (name.empty() || name.size() > 255 || name.front() == '/' || name.find('\\') != std::string::npos) return false;
    std::size_t start = 0;
    while (start <= name.size()) {
        const std::size_t end = std::min(name.find('/', start), name.size());
        const std::string part = name.substr(start, end - start);
        if (part.empty() || part == "." || part == "..") return false;
        for (char c : part)
            if (static_cast<unsigned char>(c) < 0x20) return false;
        start = end + 1;
    }
    return true;
}

bool plain_relative_brdf_name(const std::string& name) {
    return plain_relative_name(name) && name.size() >= 6 && name.compare(name.size() - 5, 5, ".brdf") == 0;
}

// A file of the page's folder as a bundle carries it, read safely (a
// regular file, at most what a link may unpack to).
std::string bundled_file(const std::string& folder, const std::string& name) {
    try {
        return io::read_input_file((std::filesystem::path(folder) / name).string(), kMaxSharedSceneBytes);
    } catch (const io::InputError& e) {
        throw std::runtime_error(std::string("share link: ") + e.what());
    }
}

// A mesh's model file and the files it names (an OBJ's .mtl, a glTF's .bin),
// by their names in the page's folder, into `files` (base64url: a .glb is binary).
void bundle_model_files(const Object& object, const std::string& name, const std::string& folder, json& files) {
    if (!plain_relative_name(name))
        throw std::runtime_error("share link: the model file " + name +
                                 " is not in the page's folder, so the link cannot carry it");
    std::vector<std::string> names{name};
    const std::filesystem::path model_folder = std::filesystem::path(name).parent_path();
    for (const std::string& side : object.model->side_files) {
        const std::string side_name = (model_folder / side).lexically_normal().generic_string();
        if (!plain_relative_name(side_name))
            throw std::runtime_error("share link: the file " + side + " that the model file " + name +
                                     " names is not in the page's folder, so the link cannot carry it");
        names.push_back(side_name);
    }
    for (const std::string& file : names)
        if (!files.contains(file)) files[file] = base64url_encode(bundled_file(folder, file));
}

std::string deflate_to_token(const std::string& text) {
    uLongf size = compressBound(uLong(text.size()));
    std::vector<Bytef> packed(size);
    if (compress2(packed.data(), &size, reinterpret_cast<const Bytef*>(text.data()), uLong(text.size()),
                  Z_BEST_COMPRESSION) != Z_OK)
        throw std::runtime_error("share link: cannot compress the scene");
    return base64url_encode(std::string(reinterpret_cast<const char*>(packed.data()), size));
}

std::string inflate_token(const std::string& token) {
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

}  // namespace

std::string share_token(const Scene& scene, const std::string& folder) {
    const json doc = scene_to_json(scene, PathWriting{folder, {}});
    json files = json::object(), model_files = json::object();
    const json objects = doc.value("objects", json::array());
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const json& object = objects[i];
        if (object.contains("file") && i < scene.objects.size() && scene.objects[i].model)
            bundle_model_files(scene.objects[i], object["file"].get<std::string>(), folder, model_files);
        const json& material = object.value("material", json::object());
        if (material.value("model", "") != "brdf") continue;
        const std::string name = material.value("file", "");
        if (files.contains(name)) continue;
        if (!plain_relative_brdf_name(name))
            throw std::runtime_error("share link: the .brdf file " + name +
                                     " is not in the page's folder, so the link cannot carry it");
        files[name] = bundled_file(folder, name);
    }
    json bundle{{"m3055_share", 1}, {"scene", doc}, {"brdf_files", files}};
    if (!model_files.empty()) bundle["model_files"] = std::move(model_files);
    const std::string text = files.empty() && !bundle.contains("model_files") ? doc.dump() : bundle.dump();
    std::string token = deflate_to_token(text);
    if (token.size() > kMaxShareTokenChars)
        throw std::runtime_error("share link: the scene and its .brdf files make a link of " +
                                 std::to_string(token.size()) + " characters, more than a browser opens (2 MB)");
    return token;
}

SharedScene unpack_share_token(const std::string& token) {
    SharedScene shared;
    std::string text = inflate_token(token);
    // A plain scene (and anything not a bundle) is loaded as it is: the loader names its errors.
    const json doc = json::parse(text, nullptr, false);
    if (!doc.is_object() || !doc.contains("m3055_share")) {
        shared.scene_text = std::move(text);
        return shared;
    }
    if (doc["m3055_share"] != 1 || !doc.contains("scene") || !doc["scene"].is_object() ||
        !doc.contains("brdf_files") || !doc["brdf_files"].is_object())
        throw std::runtime_error("share link: not a scene with its .brdf files (\"m3055_share\": 1, \"scene\", \"brdf_files\")");
    for (const auto& [name, file] : doc["brdf_files"].items()) {
        if (!plain_relative_brdf_name(name))
            throw std::runtime_error("share link: brdf_files: \"" + name + "\" is not a plain relative NAME.brdf");
        if (!file.is_string()) throw std::runtime_error("share link: brdf_files: \"" + name + "\" is not text");
        shared.files.push_back({name, file.get<std::string>()});
    }
    const json model_files = doc.value("model_files", json::object());
    if (!model_files.is_object()) throw std::runtime_error("share link: model_files is not an object of files");
    for (const auto& [name, file] : model_files.items()) {
        if (!plain_relative_name(name))
            throw std::runtime_error("share link: model_files: \"" + name + "\" is not a plain relative name");
        if (!file.is_string()) throw std::runtime_error("share link: model_files: \"" + name + "\" is not base64url text");
        shared.files.push_back({name, base64url_decode(file.get<std::string>())});
    }
    shared.scene_text = doc["scene"].dump();
    return shared;
}

}  // namespace m3055::explore
