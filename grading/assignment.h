// An assignment (`m3055 grade ASSIGNMENT.json`, docs/grading.md): the
// reference the students' renders are compared with, the tolerance and points
// of that comparison, and optional rules on the submitted scene file itself
// from a small fixed vocabulary (no scripting). Loaded and validated whole
// before any submission is looked at; every error is one line naming the file
// and the field, like the scene loader's.
#pragma once

#include "grading/level_compare.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace m3055::grading {

// Every problem of an assignment file, one line each ("FILE: field: problem");
// what() is the first, with a count of the others.
class AssignmentError : public std::runtime_error {
public:
    explicit AssignmentError(std::vector<std::string> lines);
    const std::vector<std::string>& lines() const { return lines_; }

private:
    std::vector<std::string> lines_;
};

// One rule of the vocabulary (docs/grading.md#rules). Fields unused by a kind stay at their defaults.
enum class RuleKind {
    model,        // {"rule": "model", "is": "metal", "object": 0}       (no "object": every object)
    light_count,  // {"rule": "light_count", "equals": 3, "type": "rect"} (enabled lights; of that type only with "type")
    warmer,       // {"rule": "warmer", "light": "key", "than": "fill"}
    key_to_fill,  // {"rule": "key_to_fill", "min": 2, "max": 4}          (analysis/lighting_ratio.h)
    eq14,         // {"rule": "eq14", "object": 0, "within_percent": 1}  (scene/presets.h: highlight_peak)
    range,        // {"rule": "range", "path": "objects[0].material.m", "min": 5, "max": 20}
    temperature,  // {"rule": "temperature", "light": "key", "min": 3000, "max": 3400}  (kelvin)
    equals,       // {"rule": "equals", "path": "objects[0].material.conductor", "value": "gold"}
    shadow,       // {"rule": "shadow", "light": "key"}                   (the light casts shadows)
};
const char* to_string(RuleKind kind);

struct Rule {
    RuleKind kind = RuleKind::model;
    std::string label;   // "rules[2] (key_to_fill)", or the rule's own "name"
    double points = 0;
    std::string text;    // model: the model's name; warmer: the warmer light; range, equals: the path; temperature, shadow: the light
    std::string other;   // warmer: the other light
    int object = -1;     // model, eq14: the object's index (-1: every object, model only)
    double min = 0, max = 0;  // key_to_fill, range, temperature (inclusive); light_count: min = max = N; eq14: max = percent
    nlohmann::json value;     // equals: the string or boolean the value at the path must be
    bool of_type = false;     // light_count: only lights of `light_type` are counted
    LightType light_type = LightType::directional;
};

struct Assignment {
    std::string path;       // the assignment file, as given
    std::string title;
    std::string reference;  // a scene, .png or .pfm, joined to the assignment's folder
    std::string start;      // optional: the scene a student starts from in `explore --assignment`
                            // (joined to the folder; grading ignores it), or ""
    double image_points = 0;
    Thresholds image_tolerance;  // only "fail" is used for the score (warn is ignored)
    // Partial credit: with more than fail.percent % of the pixels off, the image
    // points fall linearly to 0 at this share; 0 = none (all or nothing).
    double image_zero_percent = 0;
    // "region": "objects": only the pixels the reference scene's objects cover
    // are compared (the background may change freely); false: every pixel.
    bool image_objects_only = false;
    std::vector<Rule> rules;
    double pass_score = 0;  // a submission passes with at least this score
    double time_budget_s = 30;  // each submission's render budget (capture.h: scene_deadline)
    double max_score() const;
};

// An assignment as far as it could be read, and every problem found on the
// way (structure and ranges), one line each, in the order read, each once.
struct AssignmentRead {
    Assignment assignment;
    std::vector<std::string> errors;
    // The fields the errors are about ("image.fail_levels", "rules[2].object",
    // "rules[3]" for a rule that is not an object or of no known kind; "" for
    // a file that could not be read or parsed).
    std::vector<std::string> bad_fields;
    // Whether an error is about `field` or a field inside it ("rules[2]": any of that rule's).
    bool has_error_at(const std::string& field) const;
};
AssignmentRead read_assignment(const std::string& path);
AssignmentRead read_assignment_json(const std::string& text, const std::string& path);

// Reads and validates ASSIGNMENT.json (io/input_file.h: bounded, regular files
// only); throws AssignmentError with every problem.
Assignment load_assignment(const std::string& path);
Assignment assignment_from_json(const std::string& text, const std::string& path);

}  // namespace m3055::grading
