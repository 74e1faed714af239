#include "scene/manifest.h"

#include "io/input_file.h"
#include "io/message_text.h"
#include "scene/json_node.h"
#include "scene/json_parse.h"
#include "scene/load.h"

namespace m3055 {
namespace {

using scene_json::json;
using scene_json::Node;

// A manifest path relative to the manifest's folder; absolute paths are kept.
// Not normalized: "a/../b" through a symlinked "a" is not "b".
std::string join(const std::string& folder, const std::string& path) {
    if (path.front() == '/' || folder.empty()) return path;
    return folder + "/" + path;
}

std::string folder_of(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    if (slash == std::string::npos) return "";
    return slash == 0 ? "/" : path.substr(0, slash);
}

// The path at `key` of one entry, or "" when absent and optional.
std::string read_path(const Node& entry, const char* key, bool required) {
    if (!entry.has(key)) {
        if (required) entry.required(key);  // throws "[i].key: is required"
        return "";
    }
    const Node node = entry.child(key);
    if (!node.value().is_string()) node.fail("must be a string, got " + scene_json::describe(node.value()));
    const std::string& path = node.value().get_ref<const std::string&>();
    if (path.empty()) node.fail("must not be empty");
    if (path.find('\0') != std::string::npos)
        node.fail("must not hold a NUL character, got " + scene_json::describe(node.value()));
    return path;
}

std::vector<BatchItem> read_entries(const json& doc, const std::string& source, const std::string& folder) {
    if (!doc.is_array())
        throw ManifestError(source + ": must be a JSON array of {\"scene\", \"out\", \"raw\"} objects");
    const Node root(doc, "", source);
    std::vector<BatchItem> items;
    items.reserve(doc.size());
    for (std::size_t i = 0; i < doc.size(); ++i) {
        const Node entry = root.at(i);
        if (!entry.value().is_object()) entry.fail("must be an object, got " + scene_json::describe(entry.value()));
        entry.check_keys({"scene", "out", "raw"},
                         [](const std::string&) { return std::string("unknown key (expected scene, out, raw)"); });
        BatchItem item;
        item.entry = i;
        item.scene = join(folder, read_path(entry, "scene", true));
        item.out = join(folder, read_path(entry, "out", true));
        const std::string raw = read_path(entry, "raw", false);
        if (!raw.empty()) item.raw = join(folder, raw);
        items.push_back(std::move(item));
    }
    return items;
}

}  // namespace

std::vector<BatchItem> parse_manifest(const std::string& text, const std::string& path) {
    const std::string source = text::quote_name(path);
    try {
        return read_entries(scene_json::parse_document(text, source), source, folder_of(path));
    } catch (const SceneError& error) {
        throw ManifestError(error.what());  // the same one-line form, from the shared JSON checks
    }
}

std::vector<BatchItem> load_manifest(const std::string& path) {
    std::string text;
    try {
        text = io::read_input_file(path);
    } catch (const io::InputError& error) {
        throw ManifestError(error.what());
    }
    return parse_manifest(text, path);
}

}  // namespace m3055
