// Exact visibility against every object (reference/scene_bvh.h): the umbra a
// sphere casts where geometry says, planes blocking from both sides, the
// distance respected, a surface never hiding its own points, and the
// hierarchy agreeing with a plain loop over the objects on random rays.
#include "reference/scene_bvh.h"

#include "geometry/mesh.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace m3055::ref {
namespace {

constexpr double kFar = std::numeric_limits<double>::infinity();

Object sphere(dvec3 center, double radius) {
    Object object;
    object.center = center;
    object.radius = radius;
    return object;
}

Object plane(dvec3 center, dvec3 normal, double size) {
    Object object;
    object.shape = Shape::plane;
    object.center = center;
    object.axis = glm::normalize(normal);
    object.size = size;
    return object;
}

Scene of(std::vector<Object> objects) {
    Scene scene;
    scene.objects = std::move(objects);
    return scene;
}

TEST(SceneBvh, ASphereOverAPlaneShadowsTheDiskUnderIt) {
    const SceneBvh bvh(of({sphere({0, 2, 0}, 1), plane({0, 0, 0}, {0, 1, 0}, 10)}));
    // Light from straight above: the umbra on the floor is the disk x^2 + z^2 < 1.
    for (double x = -1.51; x <= 1.5; x += 0.125) {  // never on the tangent x = +-1
        const bool under = std::fabs(x) < 1.0;
        EXPECT_EQ(bvh.sees({x, 0, 0.0}, {0, 1, 0}, {0, 1, 0}, kFar), !under) << x;
    }
    // A light at (0, 4, 0): the umbra's edge is where the ray grazes the sphere,
    // x = 4 tan(asin(1 / 2)) = 4 / sqrt(3).
    const double edge = 4 / std::sqrt(3.0);
    for (const double x : {edge - 1e-6, edge + 1e-6}) {
        const dvec3 P(x, 0, 0), to_light = dvec3(0, 4, 0) - P;
        EXPECT_EQ(bvh.sees(P, {0, 1, 0}, glm::normalize(to_light), glm::length(to_light)), x > edge) << x;
    }
}

TEST(SceneBvh, PlanesBlockFromBothSides) {
    const SceneBvh bvh(of({plane({0, 1, 0}, {0, 1, 0}, 2)}));
    EXPECT_FALSE(bvh.sees({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, kFar));   // from below, against its back
    EXPECT_FALSE(bvh.sees({0, 2, 0}, {0, -1, 0}, {0, -1, 0}, kFar));  // from above, against its front
    EXPECT_TRUE(bvh.sees({2, 0, 0}, {0, 1, 0}, {0, 1, 0}, kFar));     // beside it
}

TEST(SceneBvh, OnlyWhatLiesBeforeTheLightBlocksIt) {
    const SceneBvh bvh(of({sphere({0, 3, 0}, 0.5)}));
    EXPECT_FALSE(bvh.sees({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, 5.0));
    EXPECT_TRUE(bvh.sees({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, 2.0));  // a point light between
    // From inside a sphere every way out is blocked (the solid blocks).
    EXPECT_FALSE(bvh.sees({0, 3, 0}, {0, 1, 0}, {0, 1, 0}, kFar));
}

TEST(SceneBvh, ASurfaceDoesNotHideItsOwnPoints) {
    const Object ball = sphere({0.3, -0.2, 1.1}, 0.7);
    const Object floor = plane({0, -1, 0}, {0, 1, 0}, 20);
    const SceneBvh bvh(of({ball, floor}));
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
        // A point on the sphere's upper half, and a direction just above its horizon (N.L down to 1e-6).
        dvec3 N = glm::normalize(dvec3(unit(rng), std::fabs(unit(rng)) + 0.05, unit(rng)));
        const dvec3 P = ball.center + ball.radius * N;
        dvec3 t = glm::normalize(glm::cross(N, dvec3(unit(rng), unit(rng), unit(rng))));
        const double lift = std::pow(10.0, -6.0 * (0.5 + 0.5 * unit(rng)));
        const dvec3 L = glm::normalize(t + lift * N);
        if (L.y > 0.0) {
            EXPECT_TRUE(bvh.sees(P, N, L, kFar)) << i;
        }
        // A floor point away from the ball, light grazing the floor.
        const dvec3 Q(5 + unit(rng), -1, 5 + unit(rng));
        EXPECT_TRUE(bvh.sees(Q, {0, 1, 0}, glm::normalize(dvec3(unit(rng), lift, std::fabs(unit(rng)))), kFar)) << i;
    }
}

// A plain loop over the objects, as the hierarchy must answer.
bool blocked_by_any(const Scene& scene, const SceneBvh& bvh, const Ray& ray, double t_max) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        if (const MeshIntersector* mesh = bvh.mesh(i)) {
            if (mesh->any_hit(ray, t_max)) return true;
            continue;
        }
        const Object& s = scene.objects[i];
        const dvec3 oc = ray.origin - s.center;
        const double b = glm::dot(oc, ray.dir), c = glm::dot(oc, oc) - s.radius * s.radius, disc = b * b - c;
        if (disc < 0) continue;
        const double t0 = -b - std::sqrt(disc), t1 = -b + std::sqrt(disc);
        if ((t0 > 0 && t0 < t_max) || (t1 > 0 && t1 < t_max)) return true;
    }
    return false;
}

TEST(SceneBvh, AgreesWithAPlainLoopOnRandomRays) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Scene scene;
    for (int i = 0; i < 60; ++i) {
        const dvec3 c(4 * unit(rng), 4 * unit(rng), 4 * unit(rng));
        Object object = sphere(c, 0.2 + 0.3 * std::fabs(unit(rng)));
        switch (i % 5) {
            case 1: object = plane(c, {unit(rng), unit(rng), 1}, 0.8); break;
            case 2: object.shape = Shape::cube, object.size = 0.5, object.rotation_deg = {20, 30, 40}; break;
            case 3: object.shape = Shape::torus, object.major_radius = 0.4, object.minor_radius = 0.1; break;
            case 4: object.shape = Shape::cylinder, object.height = 0.6; break;
        }
        scene.objects.push_back(object);
    }
    const SceneBvh bvh(scene);
    int blocked = 0;
    for (int i = 0; i < 4000; ++i) {
        const Ray ray{{5 * unit(rng), 5 * unit(rng), 5 * unit(rng)}, glm::normalize(dvec3(unit(rng), unit(rng), unit(rng)))};
        const double t_max = i % 2 ? kFar : 3 * std::fabs(unit(rng));
        const bool want = blocked_by_any(scene, bvh, ray, t_max);
        EXPECT_EQ(bvh.blocked(ray, t_max), want) << i;
        blocked += want;
    }
    EXPECT_GT(blocked, 200);  // the rays meet objects, and miss them
    EXPECT_LT(blocked, 3600);
}

TEST(SceneBvh, AnEmptySceneBlocksNothing) {
    const SceneBvh bvh(of({}));
    EXPECT_TRUE(bvh.sees({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, kFar));
}

}  // namespace
}  // namespace m3055::ref
