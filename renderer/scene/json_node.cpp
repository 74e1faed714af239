#include "scene/json_node.h"

#include "io/message_text.h"
#include "scene/load.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

namespace m3055::scene_json {

namespace {

bool is_identifier(const std::string& key) {
    if (key.empty() || key.size() > text::kMaxEchoBytes) return false;
    return std::all_of(key.begin(), key.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_' || c == '-';
    });
}

std::string dump_safe(const json& value) {
    // `replace` keeps invalid UTF-8 (possible in --set strings) from throwing.
    return value.dump(-1, ' ', false, json::error_handler_t::replace);
}

// nlohmann quotes the text it could not read: "last read: '<token>'". The
// token may be a megabyte of digits or raw Latin-1 / UTF-16 bytes; it is
// escaped and its middle cut, so the message stays one short line of UTF-8.
std::string shorten_quoted_token(const std::string& message, const std::string& marker) {
    const std::size_t open = message.find(marker);
    if (open == std::string::npos) return message;
    const std::size_t begin = open + marker.size();
    const std::size_t close = message.rfind('\'');
    if (close == std::string::npos || close < begin) return message;
    return message.substr(0, begin) + text::one_line(std::string_view(message).substr(begin, close - begin),
                                                      text::kMaxEchoBytes) +
           message.substr(close);
}

}  // namespace

std::string join_key(const std::string& path, const std::string& key) {
    if (is_identifier(key)) return path.empty() ? key : path + "." + key;
    // Quoted with escapes (a key may hold a newline or invalid UTF-8) and cut.
    return path + "[" + text::quote(key) + "]";
}

std::string join_index(const std::string& path, std::size_t index) {
    return path + "[" + std::to_string(index) + "]";
}

std::string format_number(double value) { return text::format_number(value); }

std::string describe(const json& value) {
    // Integers exactly as written (a double would round 2^53 + 1).
    if (value.is_number_unsigned()) return std::to_string(value.get<json::number_unsigned_t>());
    if (value.is_number_integer()) return std::to_string(value.get<json::number_integer_t>());
    if (value.is_number()) return format_number(value.get<double>());
    if (value.is_string()) {
        // Only the start of a long string is dumped: a 10 MB value is not copied to be cut.
        const std::string& s = value.get_ref<const std::string&>();
        if (s.size() > 4 * text::kMaxEchoBytes) return text::cut_end(dump_safe(json(s.substr(0, 4 * text::kMaxEchoBytes))));
    }
    return text::cut_end(dump_safe(value));
}

std::string json_problem(const std::string& what) {
    std::string message = what;
    if (!message.empty() && message[0] == '[') {
        const std::size_t end = message.find("] ");
        if (end != std::string::npos) message = message.substr(end + 2);
    }
    message = shorten_quoted_token(message, "last read: '");
    message = shorten_quoted_token(message, "overflow parsing '");
    // Escaped (one line, valid UTF-8); nlohmann's own text is short once its token is cut.
    return text::one_line(message, 200);
}

const Range kUnit = closed(0.0, 1.0);
const Range kCoordinate = closed(-1e6, 1e6);

void Node::fail(const std::string& problem) const {
    // A path 64 levels deep of long keys is cut in the middle, like a long file name.
    throw SceneError(source() + ": " + (path_.empty() ? "(root)" : text::one_line(path_, text::kMaxPathBytes)) +
                     ": " + problem);
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

namespace {

// "unknown key", and the allowed key a typo away from it when there is one.
std::string unknown_key_problem(const std::string& key, const std::vector<std::string>& allowed) {
    const std::string near = text::closest_name(key, allowed);
    return near.empty() ? "unknown key" : "unknown key (did you mean \"" + near + "\"?)";
}

}  // namespace

void Node::check_keys(const std::vector<std::string>& allowed,
                      const std::function<std::string(const std::string&)>& misplaced) const {
    for (const auto& item : value().items()) {
        const std::string& key = item.key();
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
        std::string problem = misplaced ? misplaced(key) : std::string();
        child(key).fail(problem.empty() ? unknown_key_problem(key, allowed) : problem);
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
    if (!range.contains(x)) fail("must be " + range.text() + ", got " + describe(value()));
    return x;
}

int Node::whole_in(int lo, int hi) const {
    const double x = number();
    if (x != std::floor(x)) fail("must be a whole number, got " + describe(value()));
    // Compare as double before converting: 1e20 must not overflow the int.
    if (x < lo || x > hi)
        fail("must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + describe(value()));
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
    // A typo's likely meaning first: a long list is cut to fit the one line.
    const std::string near = value().is_string() ? text::closest_name(value().get_ref<const std::string&>(), names) : "";
    if (!near.empty()) fail("got " + describe(value()) + ": did you mean \"" + near + "\"? (must be " + list + ")");
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
