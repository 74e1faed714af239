#include "analysis/lighting_ratio.h"

#include "reference/emitters.h"
#include "reference/reference.h"
#include "scene/area_light.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace m3055 {

namespace {

// Rec. 709 / sRGB primaries' luminance weights (linear light).
double luminance(const dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

int light_named(const Scene& scene, const char* name) {
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        if (scene.lights[i].name == name) return static_cast<int>(i);
    return -1;
}

// The integral of (N.w)+ over the part of a disk above the horizon: the
// reference's own patches (exact in the horizon's cut) integrated by its
// quadrature, the integrand scaled by a first estimate so that the tolerance
// is relative to the result.
double disk_projected_solid_angle(const Light& light, const ref::SurfacePoint& point) {
    const std::vector<ref::Patch> patches = ref::emitter_patches(light, point);
    if (patches.empty()) return 0.0;
    const auto integrate = [&](double scale, double tolerance) {
        ref::AreaIntegrand lambert;
        lambert.value = [&](const std::vector<ref::QuadratureNode>& nodes) {
            ref::Shade6 sum{};
            for (const ref::QuadratureNode& node : nodes)
                sum[0] += std::max(glm::dot(point.N, node.direction), 0.0) * node.solid_angle / scale;
            return sum;
        };
        ref::AreaQuadrature options;
        options.tolerance = tolerance;
        options.max_cells = 1 << 12;
        double total = 0.0;
        for (const ref::QuadratureNode& node : ref::integrate_area(patches, lambert, options, nullptr))
            total += std::max(glm::dot(point.N, node.direction), 0.0) * node.solid_angle;
        return total;
    };
    const double estimate = integrate(1.0, 1e-6);
    return estimate > 0.0 ? integrate(estimate, 1e-10) : 0.0;
}

}  // namespace

double irradiance_at(const Light& light, const dvec3& point, const dvec3& normal) {
    if (!light.enabled) return 0.0;
    if (!is_area_light(light.type)) {
        // ref::sample_light's scale is a_l c_l att C_spot: the same numbers the shading uses.
        const ref::LightSample sample = ref::sample_light(light, point);
        return luminance(sample.scale) * std::max(glm::dot(normal, sample.L), 0.0);
    }
    const ref::SurfacePoint at{point, normal, normal};
    const std::optional<double> projected = ref::projected_solid_angle(light, at);
    return luminance(radiance(light)) * (projected ? *projected : disk_projected_solid_angle(light, at));
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

dvec3 facing_camera(const Camera& camera, const dvec3& subject) {
    const dvec3 back = camera.position - camera.target;  // the loader keeps them apart
    const dvec3 towards = camera.projection == Projection::perspective ? camera.position - subject : back;
    return glm::length(towards) > 0.0 ? glm::normalize(towards) : glm::normalize(back);
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
    const dvec3 facing = facing_camera(scene.camera, subject);
    r.key_irradiance = irradiance_at(scene.lights[std::size_t(r.key)], subject, facing);
    r.fill_irradiance = irradiance_at(scene.lights[std::size_t(r.fill)], subject, facing);
    if (!(r.fill_irradiance > 0.0))
        return r.problem = "the fill light gives no light at the subject facing the camera", r;
    r.ratio = r.key_irradiance / r.fill_irradiance;
    r.stops = std::log2(r.ratio);
    if (!(r.ratio > 0.0)) r.problem = "the key light gives no light at the subject facing the camera";
    return r;
}

}  // namespace m3055
