// What `m3055 brdf-check` and `m3055 plot` evaluate: a model of the table by
// name, or a .brdf file, with its parameters set by NAME=VALUE texts (the
// file's own names for a .brdf; VALUE JSON: a number, [r, g, b], true/false,
// or a choice's name), and the corners of its parameter ranges.
#pragma once

#include "models/material.h"

#include <set>
#include <string>
#include <vector>

namespace m3055 {

struct BrdfTarget {
    Material material;             // the defaults with the settings applied
    std::string name;              // as the report names it
    std::set<std::string> pinned;  // table parameter names set by the user
};

// `target`: a path ending in .brdf, or a model name. Throws std::runtime_error
// (one line) for an unknown model, a translucent one (not a BRDF), an unknown
// parameter or a value of the wrong type or out of range.
BrdfTarget brdf_target(const std::string& target, const std::vector<std::string>& settings);

// The material at the corners of its number ranges and flags, the pinned ones
// left as they are: every corner for up to 5 such parameters, otherwise each
// parameter at each end alone. The first entry is `target.material` itself.
std::vector<Material> parameter_corners(const BrdfTarget& target);

}  // namespace m3055
