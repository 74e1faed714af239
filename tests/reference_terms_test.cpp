// The CPU reference's single terms and geometry (docs/spec.md#3-geometry, #4-paper-models): each checked
// against its definition at points where the answer is known in closed form.
#include "reference/reference.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace m3055::ref {
namespace {

constexpr double kTight = 1e-12;

TEST(PowSafe, ZeroToTheZeroIsOne) {
    EXPECT_EQ(pow_safe(0.0, 0.0), 1.0);
    EXPECT_EQ(pow_safe(0.3, 0.0), 1.0);
    EXPECT_EQ(pow_safe(-0.5, 0.0), 1.0);  // clamped to 0 first, then x^0 = 1
}

TEST(PowSafe, ZeroToAPositivePowerIsZero) {
    EXPECT_EQ(pow_safe(0.0, 2.0), 0.0);
    EXPECT_EQ(pow_safe(-0.25, 2.0), 0.0);  // negative base clamped to 0
    EXPECT_NEAR(pow_safe(0.5, 3.0), 0.125, kTight);
}

TEST(BeckmannD, AtTheCentreIsOneOverMSquared) {
    for (double m : {0.001, 0.05, 0.2, 0.4, 1.0, 2.0})
        EXPECT_NEAR(beckmann_D(m, 1.0), 1.0 / (m * m), 1e-12 / (m * m)) << "m = " << m;
}

TEST(BeckmannD, MatchesTheClosedFormOffCentre) {
    const double m = 0.3, alpha = 0.4;
    const double expected =
        std::exp(-std::pow(std::tan(alpha), 2) / (m * m)) / (m * m * std::pow(std::cos(alpha), 4));
    EXPECT_NEAR(beckmann_D(m, std::cos(alpha)), expected, 1e-12 * expected);
}

TEST(BeckmannD, GoesToZeroAndStaysFiniteAtGrazingHalfVector) {
    for (double m : {0.001, 0.2, 2.0}) {
        for (double NoH : {0.0, 1e-300, 1e-150, 1e-20, 1e-8, -0.5}) {
            const double D = beckmann_D(m, NoH);
            EXPECT_TRUE(std::isfinite(D)) << "m = " << m << " NoH = " << NoH;
            EXPECT_GE(D, 0.0);
            EXPECT_LT(D, 1e-100) << "m = " << m << " NoH = " << NoH;
        }
        EXPECT_EQ(beckmann_D(m, 0.0), 0.0);
    }
}

TEST(CtG, OverNoVEqualsGDividedByNoVWhereNoVIsPositive) {
    // Sweep cases where each of the three arms of the min wins.
    for (double NoH : {0.05, 0.3, 0.7, 0.99, 1.0})
        for (double NoV : {1e-6, 0.01, 0.2, 0.6, 1.0})
            for (double NoL : {1e-6, 0.05, 0.5, 1.0})
                for (double VoH : {0.05, 0.4, 0.9, 1.0}) {
                    const double expected = ct_G(NoH, NoV, NoL, VoH) / NoV;
                    EXPECT_NEAR(ct_G_over_NoV(NoH, NoV, NoL, VoH), expected, 1e-12 * expected)
                        << NoH << " " << NoV << " " << NoL << " " << VoH;
                }
}

TEST(CtG, IsTheMinimumOfItsThreeArms) {
    EXPECT_NEAR(ct_G(1.0, 1.0, 1.0, 1.0), 1.0, kTight);
    EXPECT_NEAR(ct_G(0.5, 0.2, 0.9, 0.8), 2.0 * 0.5 * 0.2 / 0.8, kTight);  // view arm
    EXPECT_NEAR(ct_G(0.5, 0.9, 0.3, 0.8), 2.0 * 0.5 * 0.3 / 0.8, kTight);  // light arm
}

TEST(CtG, OverNoVIsFiniteAtGrazingView) {
    for (double NoL : {0.0, 1e-9, 0.3, 1.0}) {
        const double g = ct_G_over_NoV(0.6, 0.0, NoL, 0.7);
        EXPECT_TRUE(std::isfinite(g)) << "NoL = " << NoL;
        EXPECT_GE(g, 0.0);
    }
    // The limit NoV -> 0 with NoL > 0 is 2 NoH / VoH.
    EXPECT_NEAR(ct_G_over_NoV(0.6, 0.0, 0.5, 0.7), 2.0 * 0.6 / 0.7, kTight);
    EXPECT_NEAR(ct_G_over_NoV(0.6, 1e-12, 0.5, 0.7), 2.0 * 0.6 / 0.7, 1e-9);
}

TEST(KayOpacity, ConstantWhenPowerIsZero) {
    for (double t_n : {0.0, 0.2, 0.8, 1.0})
        for (double NoV : {0.0, 0.3, 0.999, 1.0}) EXPECT_EQ(kay_opacity(t_n, 0.0, NoV), t_n);
}

TEST(KayOpacity, FollowsEquationSix) {
    EXPECT_NEAR(kay_opacity(0.8, 1.0, 0.25), 0.8 * 0.75, kTight);
    EXPECT_NEAR(kay_opacity(0.8, 2.0, 0.5), 0.8 * 0.25, kTight);
    EXPECT_EQ(kay_opacity(0.8, 1.0, 1.0), 0.0);   // facing the viewer: clear
    EXPECT_EQ(kay_opacity(0.8, 1.5, 0.0), 0.8);   // edge-on: t_n
    EXPECT_EQ(kay_opacity(0.8, 1.0, -0.3), 0.8);  // cos b = (N.V)+
}

Camera perspective_camera() {
    Camera camera;
    camera.position = {1.0, 2.0, 5.0};
    camera.target = {0.2, -0.3, 0.1};
    camera.up = {0.0, 1.0, 0.0};
    camera.fov_y_deg = 40.0;
    return camera;
}

TEST(CameraRay, CentrePixelOfAnOddImageLooksAlongF) {
    const Camera camera = perspective_camera();
    const dvec3 f = glm::normalize(camera.target - camera.position);
    const Ray ray = camera_ray(camera, 101, 51, 50, 25);
    EXPECT_NEAR(glm::length(ray.dir - f), 0.0, kTight);
    EXPECT_NEAR(glm::length(ray.origin - camera.position), 0.0, kTight);
}

TEST(CameraRay, PerspectiveCornersFollowSpecSection3) {
    const Camera camera = perspective_camera();
    const int w = 64, h = 48;
    const dvec3 f = glm::normalize(camera.target - camera.position);
    const dvec3 r = glm::normalize(glm::cross(f, camera.up));
    const dvec3 u_cam = glm::cross(r, f);
    const double tan_half = std::tan(20.0 * 3.14159265358979323846 / 180.0);
    // Pixel (0, 0) is the top-left: u < 0, v > 0.
    const double u = 2.0 * 0.5 / w - 1.0, v = 1.0 - 2.0 * 0.5 / h;
    const dvec3 expected = glm::normalize(f + u * tan_half * (double(w) / h) * r + v * tan_half * u_cam);
    const Ray ray = camera_ray(camera, w, h, 0, 0);
    EXPECT_NEAR(glm::length(ray.dir - expected), 0.0, kTight);
    EXPECT_LT(glm::dot(ray.dir, r), 0.0);
    EXPECT_GT(glm::dot(ray.dir, u_cam), 0.0);
    EXPECT_NEAR(glm::length(ray.dir), 1.0, kTight);
}

TEST(CameraRay, OrthographicRaysAreParallelAndSpanTheHeight) {
    Camera camera = perspective_camera();
    camera.projection = Projection::orthographic;
    camera.height = 3.0;
    const int w = 40, h = 20;
    const dvec3 f = glm::normalize(camera.target - camera.position);
    const dvec3 r = glm::normalize(glm::cross(f, camera.up));
    const dvec3 u_cam = glm::cross(r, f);
    for (int y : {0, 7, 19})
        for (int x : {0, 13, 39}) {
            const Ray ray = camera_ray(camera, w, h, x, y);
            EXPECT_NEAR(glm::length(ray.dir - f), 0.0, kTight);
            const dvec3 offset = ray.origin - camera.position;
            EXPECT_NEAR(glm::dot(offset, f), 0.0, kTight);  // origins lie in the image plane
            EXPECT_NEAR(glm::dot(offset, u_cam), 1.5 * (1.0 - 2.0 * (y + 0.5) / h), kTight);
            EXPECT_NEAR(glm::dot(offset, r), 1.5 * 2.0 * (2.0 * (x + 0.5) / w - 1.0), kTight);
        }
}

TEST(IntersectSphere, HitsTheNearFrontFace) {
    const Ray ray{{0.0, 0.0, 5.0}, {0.0, 0.0, -1.0}};
    double t = 0.0;
    ASSERT_TRUE(intersect_sphere(ray, {0.0, 0.0, 0.0}, 1.0, &t));
    EXPECT_NEAR(t, 4.0, kTight);
    // Off-centre: the hit point lies on the sphere.
    const Ray slanted{{0.3, -0.2, 5.0}, glm::normalize(dvec3(-0.1, 0.05, -1.0))};
    ASSERT_TRUE(intersect_sphere(slanted, {0.1, 0.0, 0.5}, 0.8, &t));
    const dvec3 P = slanted.origin + t * slanted.dir;
    EXPECT_NEAR(glm::length(P - dvec3(0.1, 0.0, 0.5)), 0.8, kTight);
    EXPECT_LT(glm::dot(P - dvec3(0.1, 0.0, 0.5), slanted.dir), 0.0);  // a front face
}

TEST(IntersectSphere, MissesBesideBehindAndFromInside) {
    double t = -1.0;
    EXPECT_FALSE(intersect_sphere({{0.0, 1.001, 5.0}, {0.0, 0.0, -1.0}}, {0.0, 0.0, 0.0}, 1.0, &t));
    EXPECT_FALSE(intersect_sphere({{0.0, 0.0, 5.0}, {0.0, 0.0, 1.0}}, {0.0, 0.0, 0.0}, 1.0, &t));
    EXPECT_FALSE(intersect_sphere({{0.0, 0.0, 0.2}, {0.0, 0.0, -1.0}}, {0.0, 0.0, 0.0}, 1.0, &t));
    EXPECT_EQ(t, -1.0);  // untouched on a miss
}

TEST(IntersectSphere, StaysAccurateForAFarSmallSphere) {
    // Where b^2 - c would cancel: a tiny sphere far away, hit near its edge.
    const double radius = 1e-3, distance = 1e4;
    const Ray ray{{0.0, 0.9e-3, distance}, {0.0, 0.0, -1.0}};
    double t = 0.0;
    ASSERT_TRUE(intersect_sphere(ray, {0.0, 0.0, 0.0}, radius, &t));
    const double expected = distance - std::sqrt(radius * radius - 0.9e-3 * 0.9e-3);
    EXPECT_NEAR(t, expected, 1e-11);
}

}  // namespace
}  // namespace m3055::ref
