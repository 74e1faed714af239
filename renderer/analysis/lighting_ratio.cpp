#include "analysis/lighting_ratio.h"

#include "reference/reference.h"
#include "scene/area_light.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace m3055 {

namespace {

// Rec. 709 / sRGB primaries' luminance weights (linear light).
double luminance(const dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

int light_named(const Scene& scene, const char* name) {
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        if (scene.lights[i].name == name) return static_cast<int>(i);
    return -1;
}

// Why `light`'s illuminance is not computed, or "": an area or sky light's
// would be an integral over the emitter, which this function does not do yet.
std::string no_illuminance(const Light& light, const char* role) {
    if (!is_area_light(light.type)) return {};
    return std::string("the ") + role + " light is a " + to_string(light.type) +
           " light: its illuminance is not computed by this build yet";
}

}  // namespace

double illuminance_at(const Light& light, const dvec3& point) {
    if (const std::string problem = no_illuminance(light, "given"); !problem.empty())
        throw std::invalid_argument(problem);
    // ref::sample_light's scale is a_l c_l att C_spot: the same numbers the shading uses.
    return luminance(ref::sample_light(light, point).scale);
}

dvec3 subject_centre(const Scene& scene) {
    dvec3 sum(0.0);
    int count = 0;
    for (const Object& object : scene.objects) {
        if (object.shape == Shape::plane) continue;
        sum += object.center;
        ++count;
    }
    return count ? sum / double(count) : dvec3(0.0);
}

std::string KeyFillRatio::text() const {
    if (!ok()) return problem;
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.2f:1 (%.2f stops)", ratio, stops);
    return buffer;
}

KeyFillRatio key_to_fill_ratio(const Scene& scene) { return key_to_fill_ratio(scene, subject_centre(scene)); }

KeyFillRatio key_to_fill_ratio(const Scene& scene, const dvec3& subject) {
    KeyFillRatio r;
    r.key = light_named(scene, "key");
    r.fill = light_named(scene, "fill");
    if (r.key < 0) return r.problem = "no light named \"key\"", r;
    if (r.fill < 0) return r.problem = "no light named \"fill\"", r;
    r.problem = no_illuminance(scene.lights[std::size_t(r.key)], "key");
    if (r.problem.empty()) r.problem = no_illuminance(scene.lights[std::size_t(r.fill)], "fill");
    if (!r.ok()) return r;
    r.key_illuminance = illuminance_at(scene.lights[std::size_t(r.key)], subject);
    r.fill_illuminance = illuminance_at(scene.lights[std::size_t(r.fill)], subject);
    if (!(r.fill_illuminance > 0.0)) return r.problem = "the fill light gives no light at the subject", r;
    r.ratio = r.key_illuminance / r.fill_illuminance;
    r.stops = std::log2(r.ratio);
    if (!(r.ratio > 0.0)) r.problem = "the key light gives no light at the subject";
    return r;
}

}  // namespace m3055
