#include "explore/light_plan.h"

#include "geometry/mesh.h"
#include "numeric/angles.h"
#include "scene/area_light.h"
#include "scene/light_direction.h"

#include <cmath>

namespace m3055::explore {

namespace {

using numeric::kDegree;

// `v` turned by `angle_deg` about +y, azimuth increasing (+z towards +x).
dvec3 turned_about_vertical(const dvec3& v, double angle_deg) {
    const double c = std::cos(angle_deg * kDegree), s = std::sin(angle_deg * kDegree);
    return {v.x * c + v.z * s, v.y, -v.x * s + v.z * c};
}

}  // namespace

std::vector<PlanPoint> emitter_outline(const Light& light, int rim_points) {
    std::vector<PlanPoint> outline;
    if (light.type == LightType::rect) {
        const RectFrame frame = rect_frame(light);
        const dvec3 e0 = 0.5 * light.size[0] * frame.side0, e1 = 0.5 * light.size[1] * frame.side1;
        for (const dvec3& corner : {e0 + e1, -e0 + e1, -e0 - e1, e0 - e1}) outline.push_back({corner.x, corner.z});
    } else if (light.type == LightType::disk) {
        const geometry::AxisFrame frame = geometry::axis_frame(light.normal);
        for (int k = 0; k < rim_points; ++k) {
            const double t = 2.0 * M_PI * double(k) / double(rim_points);
            const dvec3 p = light.radius * (std::cos(t) * frame.t + std::sin(t) * frame.b);
            outline.push_back({p.x, p.z});
        }
    }
    return outline;
}

void turn_to_azimuth(Light& light, const dvec3& subject, double azimuth_deg) {
    if (light.type == LightType::directional) {
        Angles angles = angles_from_direction(light.direction);
        angles.azimuth_deg = azimuth_deg;
        light.direction = direction_from_angles(angles);
        return;
    }
    const dvec3 offset = light.position - subject;
    const double radius = std::hypot(offset.x, offset.z);
    const double before_deg = std::atan2(offset.x, offset.z) / kDegree;
    light.position = subject + dvec3(radius * std::sin(azimuth_deg * kDegree), offset.y,
                                     radius * std::cos(azimuth_deg * kDegree));
    if (light.type != LightType::rect && light.type != LightType::disk) return;
    const double turn_deg = radius > 1e-12 ? azimuth_deg - before_deg : 0.0;
    light.normal = turned_about_vertical(light.normal, turn_deg);
    light.up = turned_about_vertical(light.up, turn_deg);
}

const LightPlanReadouts& update_light_plan(LightPlanReadouts& readouts, const Scene& scene, std::uint64_t revision) {
    if (readouts.revision != revision) {
        readouts.subject = subject_centre(scene);
        readouts.ratio = key_to_fill_ratio(scene, readouts.subject);
        readouts.revision = revision;
    }
    return readouts;
}

}  // namespace m3055::explore
