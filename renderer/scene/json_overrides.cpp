// `--set path=value` overrides: parse_override and apply_overrides (load.h).
// The document is edited before validation, so a bad value gets the same
// message it would get in the file.
#include "io/message_text.h"
#include "scene/json_node.h"
#include "scene/json_parse.h"
#include "scene/load.h"

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

namespace m3055 {

using scene_json::json;

namespace {

// One step of an override path: a key ("material") or an index ("[2]").
struct Step {
    bool is_index = false;
    std::string key;
    std::size_t index = 0;
};

// `key` as a JSON string: in quotes, escaped, a long one cut (io/message_text.h).
std::string quoted(const std::string& key) { return text::quote(key); }
// Command-line text as it appears in a message: as typed when plain, else
// quoted with escapes (a newline would split the one-line message); cut when long.
std::string one_line(const std::string& typed) { return text::quote_name(typed); }

[[noreturn]] void fail(const std::string& source, const std::string& path, const std::string& problem) {
    throw SceneError(source + ": --set " + one_line(path) + ": " + problem);
}

// "a.b[2].c" -> a, b, [2], c. Keys hold no '.', '[' or ']'.
std::vector<Step> parse_path(const std::string& path, const std::string& source) {
    std::vector<Step> steps;
    std::size_t i = 0;
    const auto malformed = [&]() { fail(source, path, "malformed path (expected e.g. objects[0].material.m)"); };
    while (i < path.size()) {
        if (path[i] == '[') {
            const std::size_t close = path.find(']', i);
            if (close == std::string::npos || close == i + 1) malformed();
            Step step;
            step.is_index = true;
            for (std::size_t k = i + 1; k < close; ++k) {
                if (path[k] < '0' || path[k] > '9') malformed();
                if (step.index > std::numeric_limits<std::size_t>::max() / 20) malformed();
                step.index = step.index * 10 + static_cast<std::size_t>(path[k] - '0');
            }
            steps.push_back(step);
            i = close + 1;
        } else {
            if (!steps.empty()) {
                if (path[i] != '.') malformed();  // "a[0]b"
                ++i;
            }
            const std::size_t end = path.find_first_of(".[]", i);
            const std::size_t stop = end == std::string::npos ? path.size() : end;
            if (stop == i) malformed();  // "a..b", "a.", ".a", "]"
            Step step;
            step.key = path.substr(i, stop - i);
            steps.push_back(step);
            i = stop;
        }
    }
    if (steps.empty()) malformed();
    return steps;
}

// Levels of arrays and objects in `value`, counted without recursion.
std::size_t nesting_depth(const json& value) {
    std::size_t deepest = 0;
    std::vector<std::pair<const json*, std::size_t>> todo{{&value, 0}};
    while (!todo.empty()) {
        const auto [node, depth] = todo.back();
        todo.pop_back();
        if (!node->is_structured()) continue;
        deepest = std::max(deepest, depth + 1);
        if (deepest > scene_json::kMaxNesting) break;
        for (const json& child : *node) todo.push_back({&child, depth + 1});
    }
    return deepest;
}

// The override's value: JSON when it parses as JSON, else the text as a string.
json parse_value(const Override& item, const std::string& source) {
    try {
        json value = json::parse(item.value);
        // The same limit as in files (json_parse.h): error messages dump values recursively.
        if (nesting_depth(value) > scene_json::kMaxNesting)
            fail(source, item.path,
                 "value nested deeper than " + std::to_string(scene_json::kMaxNesting) + " levels");
        return value;
    } catch (const json::out_of_range& error) {
        // "1e400" is a number, just not a finite one: say so instead of treating it as text.
        fail(source, item.path, "invalid value: " + scene_json::json_problem(error.what()));
    } catch (const json::exception&) {
        return json(item.value);
    }
}

// The path as the loader's messages write it ("lights.0.m" -> "lights[0].m"); empty when
// malformed (apply_overrides has said so).
std::string message_path(const std::string& path) {
    std::string joined;
    try {
        for (const Step& step : parse_path(path, ""))
            joined = step.is_index ? scene_json::join_index(joined, step.index) : scene_json::join_key(joined, step.key);
    } catch (const SceneError&) {
        return "";
    }
    return joined;
}

}  // namespace

SceneError blame_override(const SceneError& error, const std::vector<Override>& overrides, const std::string& source) {
    const std::string message = error.what(), prefix = source + ": ";
    if (message.rfind(prefix, 0) != 0) return error;
    // Last first: the last override wins where two set the same value, so it is the one to blame.
    std::vector<std::pair<const Override*, std::string>> paths;
    for (auto item = overrides.rbegin(); item != overrides.rend(); ++item)
        paths.emplace_back(&*item, message_path(item->path));
    for (const auto& [item, path] : paths) {
        if (path.empty() || message.compare(prefix.size(), path.size(), path) != 0) continue;
        const char next = message.size() > prefix.size() + path.size() ? message[prefix.size() + path.size()] : ':';
        if (next == ':' || next == '.' || next == '[')  // the value set, or a field inside it
            return SceneError(prefix + "--set " + one_line(item->path) + ": " + message.substr(prefix.size()));
    }
    // A field the file holds that a --set of its object's kind (a light's type, a camera's
    // projection, an object's shape, a material's model) made wrong: the file's, with the
    // --set named ("camera.height: only for orthographic cameras (with --set camera.projection)").
    for (const auto& [item, path] : paths) {
        const std::size_t dot = path.rfind('.');
        if (dot == std::string::npos) continue;
        const std::string key = path.substr(dot + 1), owner = path.substr(0, dot + 1);
        if (key != "type" && key != "projection" && key != "shape" && key != "model") continue;
        if (message.compare(prefix.size(), owner.size(), owner) == 0)
            return SceneError(message + " (with --set " + one_line(item->path) + ")");
    }
    return error;
}

Override parse_override(const std::string& text) {
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos || equals == 0)
        throw SceneError("--set " + one_line(text) + ": expected path=value");
    return Override{text.substr(0, equals), text.substr(equals + 1)};
}

void apply_overrides(json& doc, const std::vector<Override>& overrides, const std::string& source) {
    for (const Override& item : overrides) {
        const std::vector<Step> steps = parse_path(item.path, source);
        json value = parse_value(item, source);
        json* here = &doc;
        std::string walked;  // the part of the path already walked, for messages
        for (std::size_t s = 0; s < steps.size(); ++s) {
            const Step& step = steps[s];
            const bool leaf = s + 1 == steps.size();
            const std::string where = walked.empty() ? "(root)" : walked;
            if (step.is_index) {
                if (!here->is_array()) fail(source, item.path, where + " is not an array");
                const std::size_t size = here->size();
                // The leaf may also append one entry: lights[2]={...} on two lights.
                if (step.index > size || (step.index == size && !leaf))
                    fail(source, item.path,
                         "index " + std::to_string(step.index) + " out of range (" + where + " has " +
                             std::to_string(size) + (size == 1 ? " entry)" : " entries)"));
                if (leaf && step.index == size) {
                    here->push_back(std::move(value));
                    break;
                }
                here = &(*here)[step.index];
                walked = scene_json::join_index(walked, step.index);
            } else {
                if (!here->is_object()) fail(source, item.path, where + " is not an object");
                if (!leaf && !here->contains(step.key)) {
                    // A model file's material by its name (objects[i].materials.NAME.KEY)
                    // may be changed where the scene overrides none yet.
                    const bool under_object = s >= 2 && steps[s - 1].is_index && steps[s - 2].key == "objects";
                    const bool mesh_material = (step.key == "materials" && under_object) ||
                                               (s >= 3 && steps[s - 1].key == "materials" && steps[s - 2].is_index &&
                                                steps[s - 3].key == "objects");
                    if (!mesh_material) {
                        std::vector<std::string> keys;
                        for (const auto& entry : here->items()) keys.push_back(entry.key());
                        const std::string near = text::closest_name(step.key, keys);
                        fail(source, item.path,
                             "no such key " + quoted(step.key) + (near.empty() ? "" : " (did you mean " + quoted(near) + "?)"));
                    }
                    (*here)[step.key] = json::object();
                }
                here = &(*here)[step.key];
                walked = scene_json::join_key(walked, step.key);
            }
            if (leaf) *here = std::move(value);
        }
    }
}

}  // namespace m3055
