#include "batch.h"

#include "scene/load.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

namespace m3055 {
namespace {

namespace fs = std::filesystem;

// A manifest path relative to its folder; absolute paths are kept as written.
std::string resolve(const fs::path& folder, const std::string& path) {
    const fs::path p(path);
    return p.is_absolute() ? p.string() : (folder / p).lexically_normal().string();
}

// The string at `key` of entry `index`, or "" when absent and optional.
std::string read_path(const nlohmann::json& entry, const char* key, bool required, const std::string& prefix) {
    const auto found = entry.find(key);
    if (found == entry.end()) {
        if (required) throw ManifestError(prefix + "." + key + ": is required");
        return "";
    }
    if (!found->is_string()) throw ManifestError(prefix + "." + key + ": must be a string, got " + found->dump());
    if (found->get<std::string>().empty()) throw ManifestError(prefix + "." + key + ": must not be empty");
    return found->get<std::string>();
}

}  // namespace

std::vector<BatchItem> load_manifest(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw ManifestError(path + ": cannot read the file");
    std::stringstream text;
    text << file.rdbuf();
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(text.str());
    } catch (const nlohmann::json::parse_error& error) {
        throw ManifestError(path + ": invalid JSON at byte " + std::to_string(error.byte));
    }
    if (!doc.is_array()) throw ManifestError(path + ": must be a JSON array of {\"scene\", \"out\", \"raw\"} objects");

    const fs::path folder = fs::path(path).parent_path();
    std::vector<BatchItem> items;
    std::map<std::string, std::size_t> first_writer;  // output file -> entry that writes it
    for (std::size_t i = 0; i < doc.size(); ++i) {
        const std::string prefix = path + ": [" + std::to_string(i) + "]";
        const nlohmann::json& entry = doc[i];
        if (!entry.is_object()) throw ManifestError(prefix + ": must be an object, got " + entry.dump());
        for (const auto& [key, value] : entry.items()) {
            (void)value;
            if (key != "scene" && key != "out" && key != "raw")
                throw ManifestError(prefix + "." + key + ": unknown key (expected scene, out, raw)");
        }
        BatchItem item;
        item.scene = resolve(folder, read_path(entry, "scene", true, prefix));
        const std::string out = read_path(entry, "out", true, prefix);
        const std::string raw = read_path(entry, "raw", false, prefix);
        item.out = resolve(folder, out);
        if (!raw.empty()) item.raw = resolve(folder, raw);
        // Two entries writing one file would make the result depend on the order.
        for (const auto& [key, written, target] :
             {std::tuple{"out", out, item.out}, std::tuple{"raw", raw, item.raw}}) {
            if (target.empty()) continue;
            const auto [it, inserted] = first_writer.emplace(target, i);
            if (!inserted)
                throw ManifestError(prefix + "." + key + ": " + written + " is also written by entry [" +
                                    std::to_string(it->second) + "]");
        }
        items.push_back(item);
    }
    return items;
}

std::size_t run_batch(Capture& capture, const std::vector<BatchItem>& items, const BatchProgress& progress) {
    std::size_t failures = 0;
    for (std::size_t i = 0; i < items.size(); ++i) {
        std::string error;
        try {
            capture.render_to_files(load_scene_file(items[i].scene), items[i].out, items[i].raw);
        } catch (const std::exception& e) {
            error = e.what();
            ++failures;
        }
        if (progress) progress(i, items[i], error);
    }
    return failures;
}

}  // namespace m3055
