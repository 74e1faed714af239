#include "scene/scene_text.h"

#include "models/model_table.h"

#include <algorithm>
#include <cstddef>
#include <string_view>
#include <vector>

namespace m3055 {

using nlohmann::json;

namespace {

// A line's longest: a value that fits on its key's line stays there.
constexpr std::size_t kWidth = 100;

// What an object is, from where it sits: its keys' order depends on it.
enum class Kind { scene, display, camera, light, object, material, materials, other };

// The spec's order (docs/spec.md#7-scene-files): what a thing is, where it is,
// how large, how bright and in what colour, then the rest.
const std::vector<std::string_view>& key_order(Kind kind) {
    static const std::vector<std::string_view> scene = {"display", "background", "ambient", "camera", "lights",
                                                        "objects"};
    static const std::vector<std::string_view> display = {"width", "height", "bits", "dither", "view_transform"};
    static const std::vector<std::string_view> camera = {"projection", "position", "target", "up", "fov_y_deg",
                                                         "height"};
    static const std::vector<std::string_view> light = {
        "name",          "type",      "position",      "direction",  "normal",      "up",
        "size",          "radius",    "spot_direction", "spot_exponent", "intensity", "color",
        "temperature_k", "illuminant", "attenuation",  "ambient",    "lobes",       "shadow",
        "enabled"};
    static const std::vector<std::string_view> object = {
        "name",   "shape",        "file",         "center", "position", "normal", "axis", "size", "radius",
        "height", "major_radius", "minor_radius", "capped", "segments", "rotation_deg", "material", "materials"};
    static const std::vector<std::string_view> none;
    switch (kind) {
        case Kind::scene: return scene;
        case Kind::display: return display;
        case Kind::camera: return camera;
        case Kind::light: return light;
        case Kind::object: return object;
        default: return none;
    }
}

// A material: "model" first, then its model's parameters in the table's order.
std::vector<std::string_view> material_order(const json& material) {
    std::vector<std::string_view> order = {"model"};
    const auto model = material.find("model");
    if (model == material.end() || !model->is_string()) return order;
    const ModelSpec* spec = model_table().find(model->get_ref<const std::string&>());
    if (!spec) return order;
    for (const ParamSpec& param : spec->params) {
        order.push_back(param.name);
        if (!param.spectrum_key.empty()) order.push_back(param.spectrum_key);
    }
    return order;
}

// The kind of the value under `key` of an object of kind `parent` (of an
// array's elements, for an array).
Kind member_kind(Kind parent, const std::string& key) {
    switch (parent) {
        case Kind::scene:
            if (key == "display") return Kind::display;
            if (key == "camera") return Kind::camera;
            if (key == "lights") return Kind::light;
            if (key == "objects") return Kind::object;
            return Kind::other;
        case Kind::object:
            if (key == "material") return Kind::material;
            if (key == "materials") return Kind::materials;
            return Kind::other;
        case Kind::materials: return Kind::material;  // a mesh file's materials by name
        default: return Kind::other;
    }
}

// The object's keys, known ones in order first, the rest as nlohmann keeps them (sorted).
std::vector<std::string> ordered_keys(const json& object, Kind kind) {
    const std::vector<std::string_view> order =
        kind == Kind::material ? material_order(object) : key_order(kind);
    auto rank = [&](const std::string& key) {
        const auto at = std::find(order.begin(), order.end(), key);
        return std::size_t(at - order.begin());  // unknown: order.size(), after every known key
    };
    std::vector<std::string> keys;
    for (const auto& item : object.items()) keys.push_back(item.key());
    std::stable_sort(keys.begin(), keys.end(),
                     [&](const std::string& a, const std::string& b) { return rank(a) < rank(b); });
    return keys;
}

std::string scalar_text(const json& value) { return value.dump(); }

bool is_container(const json& value) { return value.is_object() || value.is_array(); }

// The value on one line: {"a": 1, "b": [1, 2]} as { "a": 1, "b": [1, 2] }.
std::string inline_text(const json& value, Kind kind) {
    if (value.is_object()) {
        if (value.empty()) return "{}";
        std::string out = "{ ";
        bool first = true;
        for (const std::string& key : ordered_keys(value, kind)) {
            if (!first) out += ", ";
            first = false;
            out += json(key).dump() + ": " + inline_text(value.at(key), member_kind(kind, key));
        }
        return out + " }";
    }
    if (value.is_array()) {
        std::string out = "[";
        for (std::size_t i = 0; i < value.size(); ++i) out += (i ? ", " : "") + inline_text(value[i], kind);
        return out + "]";
    }
    return scalar_text(value);
}

void write_value(const json& value, Kind kind, std::size_t indent, std::size_t column, bool top, std::string& out);

// An array of numbers or strings too long for one line: filled up to kWidth.
void write_filled_array(const json& array, std::size_t indent, std::string& out) {
    const std::string pad(indent + 2, ' ');
    out += "[\n" + pad;
    std::size_t column = pad.size();
    for (std::size_t i = 0; i < array.size(); ++i) {
        const std::string item = scalar_text(array[i]) + (i + 1 < array.size() ? "," : "");
        if (column > pad.size() && column + 1 + item.size() > kWidth) {
            out += "\n" + pad;
            column = pad.size();
        } else if (column > pad.size()) {
            out += " ";
            ++column;
        }
        out += item;
        column += item.size();
    }
    out += "\n" + std::string(indent, ' ') + "]";
}

// `column`: where the value starts on its line (after its key); `top`: the
// whole file, which never goes on one line.
void write_value(const json& value, Kind kind, std::size_t indent, std::size_t column, bool top, std::string& out) {
    if (!is_container(value)) {
        out += scalar_text(value);
        return;
    }
    const bool holds_containers = std::any_of(value.begin(), value.end(), is_container);
    // The scene's lights and objects: one a line, however few.
    const bool list_of_things = value.is_array() && (kind == Kind::light || kind == Kind::object);
    if (!top && !list_of_things) {
        const std::string line = inline_text(value, kind);
        if (column + line.size() + 1 <= kWidth) {  // + 1: the comma after it
            out += line;
            return;
        }
    }
    if (value.is_array() && !holds_containers) {
        write_filled_array(value, indent, out);
        return;
    }
    const std::string pad(indent + 2, ' ');
    if (value.is_array()) {
        out += "[\n";
        for (std::size_t i = 0; i < value.size(); ++i) {
            out += pad;
            write_value(value[i], kind, indent + 2, pad.size(), false, out);
            out += i + 1 < value.size() ? ",\n" : "\n";
        }
        out += std::string(indent, ' ') + "]";
        return;
    }
    out += "{\n";
    const std::vector<std::string> keys = ordered_keys(value, kind);
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const std::string head = pad + json(keys[i]).dump() + ": ";
        out += head;
        write_value(value.at(keys[i]), member_kind(kind, keys[i]), indent + 2, head.size(), false, out);
        out += i + 1 < keys.size() ? ",\n" : "\n";
    }
    out += std::string(indent, ' ') + "}";
}

}  // namespace

std::string scene_text(const nlohmann::json& scene) {
    std::string out;
    write_value(scene, Kind::scene, 0, 0, true, out);
    return out + "\n";
}

}  // namespace m3055
