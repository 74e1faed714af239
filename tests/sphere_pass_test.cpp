// passes/sphere_pass.h's CPU side: which spheres each pass draws, and the
// translucent ones' far-to-near order (the blend is only right in that order).
#include "passes/camera_frame.h"
#include "passes/sphere_pass.h"
#include "scene/presets.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <vector>

namespace m3055 {
namespace {

Object sphere(dvec3 center, double radius, const char* model) {
    Object object;
    object.shape = Shape::sphere;
    object.center = center;
    object.radius = radius;
    object.material = Material::of(model);
    return object;
}

TEST(SpherePass, SplitsOpaqueFromTranslucentAndSortsFarToNear) {
    Scene scene = default_scene();
    scene.objects = {sphere({0, 0, 0}, 0.5, "translucent"), sphere({0, 0, -3}, 0.5, "translucent"),
                     sphere({1, 0, 0}, 0.5, "highlight"), sphere({0, 0, 2}, 0.5, "translucent")};
    const CameraFrame frame = make_camera_frame(scene.camera, scene.display, scene.objects);
    const SphereSets sets = sort_spheres(scene, frame);
    ASSERT_EQ(sets.opaque.size(), 1u);
    EXPECT_EQ(sets.opaque[0].material, 2);
    ASSERT_EQ(sets.translucent.size(), 3u);
    std::vector<int> order;
    for (const auto& [key, instance] : sets.translucent) order.push_back(instance.material);
    ASSERT_GT(scene.camera.position.z, 2.5) << "the spec's camera looks down -z from in front of the spheres";
    EXPECT_EQ(order, (std::vector<int>{1, 0, 3}));
    for (std::size_t i = 1; i < sets.translucent.size(); ++i)
        EXPECT_GE(sets.translucent[i - 1].first, sets.translucent[i].first);
}

TEST(SpherePass, TheEyesPowerOrdersUnequalSpheresExactly) {
    // Two disjoint spheres: the big one's centre is the farther, its surface
    // the nearer. By their centres the big one would be drawn first, wrongly.
    Scene scene = default_scene();
    const Object big = sphere({0, 0, -2}, 3.0, "translucent"), small = sphere({3.97, 0, 0}, 0.1, "translucent");
    scene.objects = {big, small};
    const CameraFrame frame = make_camera_frame(scene.camera, scene.display, scene.objects);
    ASSERT_GT(glm::length(big.center - frame.position), glm::length(small.center - frame.position));
    ASSERT_GT(glm::length(big.center - small.center), big.radius + small.radius);
    EXPECT_GT(far_to_near_sphere_key(frame, small), far_to_near_sphere_key(frame, big));
}

TEST(SpherePass, SpheresOffTheScreenAreNotDrawn) {
    Scene scene = default_scene();
    scene.objects = {sphere({0, 0, 0}, 0.5, "highlight"), sphere({0, 0, 100}, 0.5, "highlight")};
    const CameraFrame frame = make_camera_frame(scene.camera, scene.display, scene.objects);
    EXPECT_EQ(sort_spheres(scene, frame).opaque.size(), 1u) << "the one behind the camera";
}

}  // namespace
}  // namespace m3055
