// An interval for range checks: what the scene loader enforces and what the
// model table states for every parameter (models/model_spec.h).
#pragma once

#include <string>

namespace m3055::scene_json {

// Upper bound +inf is printed as "> lo" / ">= lo".
struct Range {
    double lo;
    double hi;
    bool lo_open = false;
    bool hi_open = false;
    bool contains(double x) const;
    std::string text() const;  // "in [0, 1]", "in (0, 180)", "> 0"
};

// [lo, hi].
Range closed(double lo, double hi);

}  // namespace m3055::scene_json

namespace m3055 {
using scene_json::closed;
using scene_json::Range;
}  // namespace m3055
