// The key-to-fill ratio of a lit subject (three-point lighting): the
// irradiance the light named "key" delivers at the subject's centre, on a
// surface facing the camera, against the one named "fill", as n:1 and in
// photographic stops (log2). The explorer shows it live and grading rules
// check it, through this one function.
#pragma once

#include "scene/scene.h"

#include <string>

namespace m3055 {

// What `light` delivers at `point` to a surface of unit normal `normal`, as
// luminance (Rec. 709 Y of the linear colour): for a directional, point or
// spot light a_l Y(c_l) att(r) C_spot (N.L)+; for a rect or disk Y(L) times
// the projected solid angle of the emitter above the horizon (Lambert's
// polygon formula; the disk's converged quadrature); for the sky Y(L) pi
// (1 + N.up) / 2. 0 for a disabled light, or one behind the surface. Nothing
// is shadowed: the subject stands where it is measured, as an incident-light
// meter held in its place (docs/grading.md#rules).
double irradiance_at(const Light& light, const dvec3& point, const dvec3& normal);

// The subject's centre: the centroid of the objects' centres, floors (planes)
// left out; the origin for a scene without such objects.
dvec3 subject_centre(const Scene& scene);

// The unit normal at `subject` facing the camera: towards its position
// (perspective) or against its view direction (orthographic).
dvec3 facing_camera(const Camera& camera, const dvec3& subject);

struct KeyFillRatio {
    int key = -1, fill = -1;  // the lights' indices
    double key_irradiance = 0.0, fill_irradiance = 0.0;
    double ratio = 0.0;       // key / fill
    double stops = 0.0;       // log2(ratio)
    std::string problem;      // why there is no ratio ("no light named \"fill\""), or ""
    bool ok() const { return problem.empty(); }
    std::string text() const;  // "2.50:1 (1.32 stops)", or the problem
};

// The ratio at `subject` (subject_centre(scene) by default), facing the
// scene's camera, between the lights named "key" and "fill" (the first of each name).
KeyFillRatio key_to_fill_ratio(const Scene& scene);
KeyFillRatio key_to_fill_ratio(const Scene& scene, const dvec3& subject);

}  // namespace m3055
