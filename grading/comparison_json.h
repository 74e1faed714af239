// A Comparison as JSON (`m3055 compare --json`, grades.json): one object,
// field names documented in docs/grading.md.
#pragma once

#include "grading/level_compare.h"

#include <nlohmann/json.hpp>

namespace m3055::grading {

nlohmann::json to_json(const Comparison& comparison);

// "pass: 99.87 % of pixels on the same level, 213 on another (max 2 levels)", and with
// --fail-levels N > 0 ", 0 more than N levels off" after it.
std::string summary_line(const Comparison& comparison);

}  // namespace m3055::grading
