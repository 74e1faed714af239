#include "scene/area_light.h"

#include "numeric/angles.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>

namespace m3055 {

bool is_area_light(LightType type) {
    return type == LightType::rect || type == LightType::disk || type == LightType::sky;
}

dvec3 default_rect_up(const dvec3& normal) {
    static const double kWithinOneDegree = std::cos(numeric::kDegree);
    return std::fabs(normal.y) >= kWithinOneDegree ? dvec3(0.0, 0.0, -1.0) : dvec3(0.0, 1.0, 0.0);
}

RectFrame rect_frame(const Light& light) {
    const dvec3 n = light.normal;
    // Gram-Schmidt; the loader keeps `up` at least 1e-6 rad away from the normal.
    const dvec3 side1 = glm::normalize(light.up - glm::dot(light.up, n) * n);
    return {glm::cross(n, side1), side1, n};
}

double emitter_area(const Light& light) {
    switch (light.type) {
        case LightType::rect: return light.size[0] * light.size[1];
        case LightType::disk: return numeric::kPi * light.radius * light.radius;
        default: throw std::logic_error(std::string(to_string(light.type)) + " lights have no emitting area");
    }
}

dvec3 radiance(const Light& light) {
    const dvec3 emitted = light.intensity * light.color;
    if (light.type == LightType::sky) return emitted / numeric::kPi;
    return emitted / emitter_area(light);
}

}  // namespace m3055
