// The reference's stated error on real models (reference/lit_point.h,
// docs/reference.md): an area or sky light integrated with the default
// AreaQuadrature lies within its own error estimate of one integrated a
// hundred times more tightly, for very sharp lobes, the highlight centred on
// the emitter, with and without a shadow across it; and within the default
// cell budget, but for GGX of roughness 1e-3 peaking at a rect's centre.
#include "reference/lit_point.h"
#include "reference/reference.h"
#include "reference/scene_bvh.h"

#include "scene/area_light.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace m3055::ref {
namespace {

Material sharp(const std::string& name) {
    Material m = Material::of(name);
    if (name == "phong") m.set_number("shininess", 10000);
    if (name == "highlight") m.set_number("m", 10);
    if (name == "metal") m.set_lobes({{1e-4, 0.001}, {0.1, 0.4}});
    if (name == "microfacet") {
        m.set_choice("distribution", "ggx");
        m.set_lobes({{1.0, 0.001}});
    }
    return m;
}

std::vector<Light> lights_over(const dvec3& centre) {
    Light rect;
    rect.type = LightType::rect;
    rect.position = centre;
    rect.normal = glm::normalize(dvec3(0, -1, -0.2));
    rect.up = default_rect_up(rect.normal);
    rect.size[0] = 1.5, rect.size[1] = 1.0;
    rect.intensity = 4.0;
    Light disk = rect;
    disk.type = LightType::disk;
    disk.radius = 0.6;
    Light sky;
    sky.type = LightType::sky;
    return {rect, disk, sky};
}

double largest(const dvec3& c) { return std::max({std::fabs(c.r), std::fabs(c.g), std::fabs(c.b)}); }

TEST(AreaLightError, SharpLobesUnderEveryAreaLightAreWithinTheStatedTolerance) {
    const dvec3 centre(0, 3, 0.5);
    // A floor point whose mirror direction meets the emitter's centre: the lobe's peak on it.
    const dvec3 N(0, 1, 0), R = glm::normalize(centre);
    const SurfacePoint p{dvec3(0.0), N, 2 * glm::dot(N, R) * N - R};
    Scene scene;  // a ball across part of the way to the emitter
    Object ball;
    ball.center = {0.35, 1.5, 0.2};
    ball.radius = 0.3;
    scene.objects = {ball};
    const SceneBvh occluders(scene);
    AreaQuadrature tight;
    tight.tolerance /= 100, tight.shadow_tolerance /= 100, tight.max_cells = 1 << 16;
    for (const std::string name : {"phong", "highlight", "metal", "microfacet"}) {
        const Material material = sharp(name);
        for (Light light : lights_over(centre))
            for (const bool shadow : {false, true}) {
                light.shadow = shadow;
                AreaStats stats, tight_stats;
                const dvec3 got = shade_opaque(material, {light}, p, dvec3(0.0), {&occluders, {}, &stats});
                const dvec3 want = shade_opaque(material, {light}, p, dvec3(0.0), {&occluders, tight, &tight_stats});
                const std::string what = name + " " + to_string(light.type) + (shadow ? " shadowed" : "");
                // Each run's own estimate (relative to max(1, |colour|)) bounds its error: together, their gap.
                const double tolerance = shadow ? AreaQuadrature{}.shadow_tolerance : AreaQuadrature{}.tolerance;
                const double stated = std::max(tolerance, stats.worst_error) * std::max(1.0, largest(got)) +
                                      tight_stats.worst_error * std::max(1.0, largest(want));
                EXPECT_LE(largest(got - want), stated) << what;
                // Within the default cell budget everywhere but under GGX's 1e-3 peak (docs/reference.md).
                if (name != "microfacet") {
                    EXPECT_EQ(stats.unconverged, 0) << what;
                }
                std::printf("%-28s |got - want| %.2e  stated %.2e  cells %lld unconverged %lld\n", what.c_str(),
                            largest(got - want), stated, stats.cells, stats.unconverged);
                EXPECT_GT(largest(want), 0.0) << what;
            }
    }
}

}  // namespace
}  // namespace m3055::ref
