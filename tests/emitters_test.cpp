// Where a point sees an area or sky light (reference/emitters.h): the closed
// forms of the projected solid angle against textbook view factors, and the
// quadrature's patches against the closed forms, horizon cuts included.
#include "reference/emitters.h"

#include "numeric/angles.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace m3055::ref {
namespace {

using numeric::kPi;

Light rect(dvec3 position, dvec3 normal, double w, double h, dvec3 up = {0, 0, -1}) {
    Light light;
    light.type = LightType::rect;
    light.position = position;
    light.normal = glm::normalize(normal);
    light.up = glm::normalize(up);
    light.size[0] = w;
    light.size[1] = h;
    return light;
}

Light disk(dvec3 position, dvec3 normal, double radius) {
    Light light;
    light.type = LightType::disk;
    light.position = position;
    light.normal = glm::normalize(normal);
    light.radius = radius;
    return light;
}

Light sky(dvec3 up = {0, 1, 0}) {
    Light light;
    light.type = LightType::sky;
    light.up = glm::normalize(up);
    return light;
}

SurfacePoint at(dvec3 P, dvec3 N) { return {P, glm::normalize(N), glm::normalize(N)}; }

// Integral of f(w) dw over the patches by the midpoint rule, 400 x 400 a
// patch: independent of the engine, accurate to about 1e-6 on these smooth maps.
template <typename F>
double integrate(const std::vector<Patch>& patches, F f) {
    constexpr int n = 400;
    double sum = 0.0;
    for (const Patch& patch : patches)
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const PatchSample s = patch((i + 0.5) / n, (j + 0.5) / n);
                sum += f(s.direction) * s.density / (double(n) * n);
            }
    return sum;
}

// The view factor of a differential area to a parallel rectangle a x b whose
// corner lies on its normal at distance c (Howell's catalog, B-3), times pi.
double corner_rectangle(double a, double b, double c) {
    const double A = a / c, B = b / c;
    return 0.5 * (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
                  B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B)));
}

TEST(Emitters, LambertsFormulaGivesTheViewFactorOfARectangleOverhead) {
    // Centred 2 x 1 at height 1.5: four corner rectangles 1 x 0.5.
    const Light light = rect({0, 1.5, 0}, {0, -1, 0}, 2.0, 1.0);
    EXPECT_NEAR(*projected_solid_angle(light, at({0, 0, 0}, {0, 1, 0})), 4 * corner_rectangle(1.0, 0.5, 1.5), 1e-14);
    // Off centre, one corner above the point: the rectangle 2 x 1 from its corner.
    EXPECT_NEAR(*projected_solid_angle(light, at({-1, 0, -0.5}, {0, 1, 0})), corner_rectangle(2.0, 1.0, 1.5), 1e-14);
}

TEST(Emitters, ARectBehindThePointOrBelowItsHorizonGivesNothing) {
    const Light light = rect({0, 1.5, 0}, {0, -1, 0}, 2.0, 1.0);
    EXPECT_EQ(*projected_solid_angle(light, at({0, 2, 0}, {0, 1, 0})), 0.0);    // behind its emitting side
    EXPECT_EQ(*projected_solid_angle(light, at({0, 0, 0}, {0, -1, 0})), 0.0);   // below the horizon
    EXPECT_TRUE(emitter_patches(light, at({0, 2, 0}, {0, -1, 0})).empty());
    EXPECT_TRUE(emitter_patches(light, at({0, 0, 0}, {0, -1, 0})).empty());
}

TEST(Emitters, RectPatchesCoverItsSolidAngleAndItsProjectedSolidAngle) {
    // A square of side s centred on the axis at distance d: 4 asin(s^2 / (s^2 + 4 d^2)).
    const Light light = rect({0, 2, 0}, {0, -1, 0}, 1.0, 1.0);
    const std::vector<Patch> patches = emitter_patches(light, at({0, 0, 0}, {0, 1, 0}));
    EXPECT_NEAR(integrate(patches, [](const dvec3&) { return 1.0; }), 4 * std::asin(1.0 / 17.0), 1e-6);
    // Tilted and cut by the horizon: the patches cover exactly the part Lambert's formula sees.
    for (const dvec3& N : {dvec3(1, 0.2, 0), dvec3(1, 1, 0.3), dvec3(-0.2, 0.05, 1)}) {
        const SurfacePoint p = at({0.3, 0, 0.1}, N);
        const double projected = *projected_solid_angle(light, p);
        EXPECT_GT(projected, 0.0);
        EXPECT_NEAR(integrate(emitter_patches(light, p), [&](const dvec3& w) { return glm::dot(p.N, w); }), projected,
                    1e-6 * projected)
            << N.x << " " << N.y << " " << N.z;
    }
}

TEST(Emitters, DiskPatchesGiveTheDiskOnItsAxis) {
    // A Lambertian disk of radius R seen from its axis at distance h: pi R^2 / (h^2 + R^2).
    const double R = 0.7, h = 1.3;
    const Light light = disk({0, 0, h}, {0, 0, -1}, R);
    const SurfacePoint p = at({0, 0, 0}, {0, 0, 1});
    EXPECT_NEAR(integrate(emitter_patches(light, p), [&](const dvec3& w) { return w.z; }), kPi * R * R / (h * h + R * R),
                1e-6);
    EXPECT_FALSE(projected_solid_angle(light, p).has_value());  // no closed form off the axis: none at all
}

TEST(Emitters, DiskCutByTheHorizonIsTheSegmentAboveIt) {
    // A disk standing on edge over a tilted surface: the patches against a brute-force sum over the disk.
    const Light light = disk({0.2, 0.4, 1}, {0.1, -0.3, -1}, 0.8);
    const SurfacePoint p = at({0, 0, 0}, {0.2, 1, 0.3});
    double brute = 0.0;
    constexpr int n = 1500;
    const dvec3 ex = glm::normalize(glm::cross(light.normal, dvec3(1, 0, 0))), ey = glm::cross(light.normal, ex);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double x = -light.radius + 2 * light.radius * (i + 0.5) / n, y = -light.radius + 2 * light.radius * (j + 0.5) / n;
            if (x * x + y * y > light.radius * light.radius) continue;
            const dvec3 d = light.position + x * ex + y * ey - p.P;
            const double r = glm::length(d), NoW = glm::dot(p.N, d / r);
            if (NoW > 0.0) brute += NoW * -glm::dot(light.normal, d / r) / (r * r) * std::pow(2 * light.radius / n, 2);
        }
    const double patches = integrate(emitter_patches(light, p), [&](const dvec3& w) { return glm::dot(p.N, w); });
    EXPECT_GT(patches, 0.0);
    EXPECT_NEAR(patches, brute, 2e-4 * brute);
}

TEST(Emitters, TheSkyAboveBothHorizonsIsALune) {
    for (const double tilt_deg : {0.0, 30.0, 90.0, 150.0, 180.0}) {
        const double tilt = tilt_deg * kPi / 180.0;
        const SurfacePoint p = at({0, 0, 0}, {std::sin(tilt), std::cos(tilt), 0});
        const double lune = 0.5 * kPi * (1 + std::cos(tilt));  // pi (1 + N.up) / 2
        EXPECT_NEAR(*projected_solid_angle(sky(), p), lune, 1e-15) << tilt_deg;
        const std::vector<Patch> patches = emitter_patches(sky(), p);
        EXPECT_NEAR(integrate(patches, [&](const dvec3& w) { return glm::dot(p.N, w); }), lune, 1e-5) << tilt_deg;
        // Its solid angle: the lune's angle (pi - tilt) times 2.
        EXPECT_NEAR(integrate(patches, [](const dvec3&) { return 1.0; }), 2 * (kPi - tilt), 1e-5) << tilt_deg;
        for (const Patch& patch : patches) {
            const dvec3 w = patch(0.3, 0.6).direction;
            EXPECT_GE(w.y, -1e-15);
            EXPECT_GE(glm::dot(w, p.N), -1e-15);
        }
    }
}

}  // namespace
}  // namespace m3055::ref
