// The key-to-fill ratio of a lit subject (three-point lighting): the
// illuminance the light named "key" delivers at the subject's centre against
// the one named "fill", as n:1 and in photographic stops (log2). The explorer
// shows it live and grading rules check it, through this one function.
#pragma once

#include "scene/scene.h"

#include <string>

namespace m3055 {

// What `light` delivers at `point` to a surface facing it, as luminance:
// a_l Y(c_l) att(r) C_spot, Y the Rec. 709 luminance of the (linear) light
// colour; 0 for a disabled light. (No N.L: "facing it" is the lit side.)
double illuminance_at(const Light& light, const dvec3& point);

// The subject's centre: the centroid of the objects' centres, floors (planes)
// left out; the origin for a scene without such objects.
dvec3 subject_centre(const Scene& scene);

struct KeyFillRatio {
    int key = -1, fill = -1;  // the lights' indices
    double key_illuminance = 0.0, fill_illuminance = 0.0;
    double ratio = 0.0;       // key / fill
    double stops = 0.0;       // log2(ratio)
    std::string problem;      // why there is no ratio ("no light named \"fill\""), or ""
    bool ok() const { return problem.empty(); }
    std::string text() const;  // "2.50:1 (1.32 stops)", or the problem
};

// The ratio at `subject` (subject_centre(scene) by default) between the lights
// named "key" and "fill" (the first of each name).
KeyFillRatio key_to_fill_ratio(const Scene& scene);
KeyFillRatio key_to_fill_ratio(const Scene& scene, const dvec3& subject);

}  // namespace m3055
