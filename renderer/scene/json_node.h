// A JSON value together with the place it sits in the scene file, so that every
// check can report "SOURCE: json.path: problem" as one line (docs/spec.md#7-scene-files).
#pragma once

#include "models/range.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

namespace m3055::scene_json {

using nlohmann::json;

// "a.b" / "a[3]": appends one step to a path. Keys that are not plain identifiers
// are written as ["..."] with JSON escapes, so a message can never span two lines.
std::string join_key(const std::string& path, const std::string& key);
std::string join_index(const std::string& path, std::size_t index);

// Shortest text that reads back as the same double ("-3", "12.5", "0.001", "1e+20").
std::string format_number(double value);
// A JSON value as it would appear in the file, shortened when long; never throws.
std::string describe(const json& value);

// nlohmann's exception text without its "[json.exception.parse_error.101] " tag,
// on one line: "parse error at line 3, column 5: syntax error ...".
std::string json_problem(const std::string& what);

// Ranges the format uses in several places (Range: models/range.h).
extern const Range kUnit;         // colours, d, w, t_n: [0, 1]
extern const Range kCoordinate;   // positions and centres: [-1e6, 1e6] (keeps r^2 finite)

class Node {
public:
    Node(const json& value, std::string path, const std::string& source)
        : value_(&value), path_(std::move(path)), source_(&source) {}

    const json& value() const { return *value_; }
    const std::string& path() const { return path_; }
    const std::string& source() const { return *source_; }

    // Throws SceneError("SOURCE: PATH: problem").
    [[noreturn]] void fail(const std::string& problem) const;

    // Objects.
    void expect_object() const;                       // "must be an object"
    bool has(const std::string& key) const;
    Node child(const std::string& key) const;         // key must exist
    Node required(const std::string& key) const;      // "KEY: is required"
    // Every key must be in `allowed`; for any other key, `misplaced(key)` gives the
    // problem ("only for spot lights") or "" for a plain "unknown key".
    void check_keys(const std::vector<std::string>& allowed,
                    const std::function<std::string(const std::string&)>& misplaced = {}) const;

    // Arrays: "must be an array"; then the entry count must lie in [min, max],
    // else "must have <what_range>, got N" (what_range e.g. "1 to 4 lobes").
    std::size_t array_size(std::size_t min, std::size_t max, const std::string& what_range) const;
    Node at(std::size_t index) const;

    // Scalars.
    double number() const;                      // finite number
    double number_in(const Range& range) const;
    int whole_in(int lo, int hi) const;         // integral value (12.0 accepted)
    bool boolean() const;
    // Index into `names` of the string this node holds: 'must be "a" or "b", got X'.
    std::size_t one_of(const std::vector<std::string>& names) const;

    // Vectors: exactly 3 finite numbers ("must be an array of 3 numbers").
    dvec3 vec3() const;
    dvec3 vec3_in(const Range& range) const;    // each component, reported as path[i]
    dvec3 direction() const;                    // non-zero, returned as a unit vector

private:
    const json* value_;
    std::string path_;
    const std::string* source_;
};

// Unit vector along v (v finite, non-zero). Idempotent: a vector that is already
// unit to within rounding is returned unchanged, so saving and re-loading a scene
// gives back exactly the same directions. Scales first so tiny or huge inputs work.
dvec3 unit_vector(const dvec3& v);

// A list of 1 to kMaxLobes lobes {"w", KEY}: weights in `weight`, KEY values in
// `value`. The other lobe key (`other`) is rejected as "not a parameter of
// OWNER (its lobes use "w" and "KEY")", e.g. owner = "model metal_blinn".
std::vector<Lobe> read_lobe_list(const Node& node, const std::string& key, const std::string& other,
                                 const Range& weight, const Range& value, const std::string& owner);

}  // namespace m3055::scene_json
