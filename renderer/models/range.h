// An interval for range checks: what the scene loader enforces and what the
// model table states for every parameter (models/model_spec.h).
#pragma once

#include <string>

namespace m3055 {

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

}  // namespace m3055

namespace m3055::scene_json {  // the loader's name for them
using m3055::closed;
using m3055::Range;
}  // namespace m3055::scene_json
