#include "scene/json_node.h"

#include "scene/load.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace m3055::scene_json {

namespace {

bool is_identifier(const std::string& key) {
    if (key.empty()) return false;
    return std::all_of(key.begin(), key.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_' || c == '-';
    });
}

std::string dump_safe(const json& value) {
    // `replace` keeps invalid UTF-8 (possible in --set strings) from throwing.
    return value.dump(-1, ' ', false, json::error_handler_t::replace);
}

}  // namespace

std::string join_key(const std::string& path, const std::string& key) {
    if (is_identifier(key)) return path.empty() ? key : path + "." + key;
    return path + "[" + dump_safe(json(key)) + "]";
}

std::string join_index(const std::string& path, std::size_t index) {
    return path + "[" + std::to_string(index) + "]";
}

std::string format_number(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buffer[40];
    if (value == std::floor(value) && std::fabs(value) < 1e15) {
        std::snprintf(buffer, sizeof buffer, "%.0f", value);
        return value == 0.0 ? "0" : buffer;  // no "-0"
    }
    for (int precision = 1; precision <= 17; ++precision) {
        std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
        if (std::strtod(buffer, nullptr) == value) break;
    }
    return buffer;
}

std::string describe(const json& value) {
    if (value.is_number()) return format_number(value.get<double>());
    std::string text = dump_safe(value);
    constexpr std::size_t kMax = 40;
    if (text.size() > kMax) text = text.substr(0, kMax) + "...";
    return text;
}

std::string json_problem(const std::string& what) {
    std::string text = what;
    if (!text.empty() && text[0] == '[') {
        const std::size_t end = text.find("] ");
        if (end != std::string::npos) text = text.substr(end + 2);
    }
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    return text;
}

bool Range::contains(double x) const {
    const bool above = lo_open ? x > lo : x >= lo;
    const bool below = hi_open ? x < hi : x <= hi;
    return above && below;
}

std::string Range::text() const {
    if (std::isinf(hi)) return (lo_open ? "> " : ">= ") + format_number(lo);
    return std::string("in ") + (lo_open ? "(" : "[") + format_number(lo) + ", " +
           format_number(hi) + (hi_open ? ")" : "]");
}

Range closed(double lo, double hi) { return Range{lo, hi}; }
const Range kUnit = closed(0.0, 1.0);
const Range kCoordinate = closed(-1e6, 1e6);

void Node::fail(const std::string& problem) const {
    throw SceneError(source() + ": " + (path_.empty() ? "(root)" : path_) + ": " + problem);
}

void Node::expect_object() const {
    if (!value().is_object()) fail("must be an object");
}

bool Node::has(const std::string& key) const { return value().contains(key); }

Node Node::child(const std::string& key) const {
    return Node(value().at(key), join_key(path_, key), source());
}

Node Node::required(const std::string& key) const {
    if (!has(key)) Node(value(), join_key(path_, key), source()).fail("is required");
    return child(key);
}

void Node::check_keys(const std::vector<std::string>& allowed,
                      const std::function<std::string(const std::string&)>& misplaced) const {
    for (const auto& item : value().items()) {
        const std::string& key = item.key();
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
        std::string problem = misplaced ? misplaced(key) : std::string();
        child(key).fail(problem.empty() ? "unknown key" : problem);
    }
}

std::size_t Node::array_size(std::size_t min, std::size_t max,
                             const std::string& what_range) const {
    if (!value().is_array()) fail("must be an array");
    const std::size_t size = value().size();
    if (size < min || size > max) fail("must have " + what_range + ", got " + std::to_string(size));
    return size;
}

Node Node::at(std::size_t index) const {
    return Node(value().at(index), join_index(path_, index), source());
}

double Node::number() const {
    if (!value().is_number()) fail("must be a number, got " + describe(value()));
    const double x = value().get<double>();
    if (!std::isfinite(x)) fail("must be a finite number");
    return x;
}

double Node::number_in(const Range& range) const {
    const double x = number();
    if (!range.contains(x)) fail("must be " + range.text() + ", got " + format_number(x));
    return x;
}

int Node::whole_in(int lo, int hi) const {
    const double x = number();
    if (x != std::floor(x)) fail("must be a whole number, got " + format_number(x));
    // Compare as double before converting: 1e20 must not overflow the int.
    if (x < lo || x > hi)
        fail("must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
             format_number(x));
    return static_cast<int>(x);
}

bool Node::boolean() const {
    if (!value().is_boolean()) fail("must be true or false, got " + describe(value()));
    return value().get<bool>();
}

std::size_t Node::one_of(const std::vector<std::string>& names) const {
    if (value().is_string()) {
        const auto& text = value().get_ref<const std::string&>();
        const auto found = std::find(names.begin(), names.end(), text);
        if (found != names.end()) return static_cast<std::size_t>(found - names.begin());
    }
    std::string list;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) list += i + 1 == names.size() ? " or " : ", ";
        list += "\"" + names[i] + "\"";
    }
    fail("must be " + list + ", got " + describe(value()));
}

dvec3 Node::vec3() const {
    const json& v = value();
    if (!v.is_array() || v.size() != 3 ||
        !std::all_of(v.begin(), v.end(), [](const json& e) { return e.is_number(); }))
        fail("must be an array of 3 numbers");
    return dvec3(at(0).number(), at(1).number(), at(2).number());
}

dvec3 Node::vec3_in(const Range& range) const {
    vec3();  // shape first, so "[1, 2]" reads as a shape error, not a range error
    return dvec3(at(0).number_in(range), at(1).number_in(range), at(2).number_in(range));
}

dvec3 Node::direction() const {
    const dvec3 v = vec3();
    if (v.x == 0.0 && v.y == 0.0 && v.z == 0.0) fail("must be non-zero");
    return unit_vector(v);
}

dvec3 unit_vector(const dvec3& v) {
    constexpr double kEps = std::numeric_limits<double>::epsilon();
    const double length2 = v.x * v.x + v.y * v.y + v.z * v.z;
    if (std::fabs(length2 - 1.0) <= 8.0 * kEps) return v;  // already unit: keep bit-exact
    // Divide by the largest component first so neither x^2 overflows nor underflows.
    const double scale = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    const dvec3 s = v / scale;
    return s / std::sqrt(s.x * s.x + s.y * s.y + s.z * s.z);
}

std::vector<Lobe> read_lobe_list(const Node& node, const std::string& key, const std::string& other,
                                 const Range& weight, const Range& value, const std::string& owner) {
    const std::size_t count = node.array_size(1, kMaxLobes, "1 to 4 lobes");
    std::vector<Lobe> lobes;
    for (std::size_t i = 0; i < count; ++i) {
        const Node entry = node.at(i);
        entry.expect_object();
        entry.check_keys({"w", key}, [&](const std::string& k) {
            if (k != other) return std::string();
            return "not a parameter of " + owner + " (its lobes use \"w\" and \"" + key + "\")";
        });
        Lobe lobe;
        lobe.w = entry.required("w").number_in(weight);
        lobe.m = entry.required(key).number_in(value);
        lobes.push_back(lobe);
    }
    return lobes;
}

}  // namespace m3055::scene_json
