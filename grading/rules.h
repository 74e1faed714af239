// The rule vocabulary of an assignment (assignment.h, docs/grading.md#rules)
// checked on a submitted scene, each with a one-line reason.
#pragma once

#include "grading/assignment.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <string>

namespace m3055::grading {

// One scored item of a grade: the image comparison or a rule.
struct Check {
    std::string label;  // "image", or the rule's label
    double points = 0, earned = 0;
    bool ok = false;
    std::string reason;  // one line, whether it passed or not ("3 lights enabled, not 2")
};

// `document` is scene_to_json(scene): the scene with every default written
// out, so a range rule finds a parameter the student left at its default.
Check check_rule(const Rule& rule, const Scene& scene, const nlohmann::json& document);

// The value at a rule's path ("objects[0].material.m") in a scene's JSON, or
// nullptr when the path is not there or not a path: the range rule and
// `grade --check` read paths the same way.
const nlohmann::json* find_scene_value(const nlohmann::json& document, const std::string& path);

// Whether two names differ only in the case of ASCII letters ("Key", "key"):
// light names and values are compared exactly, and a reason says so then.
bool same_but_case(const std::string& a, const std::string& b);

}  // namespace m3055::grading
