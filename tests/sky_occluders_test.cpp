// The objects as a shadowed sky's samples are drawn about them
// (passes/occluders.h: SkyOccluder): the shapes whose silhouettes the GPU
// integrates in closed form (glsl/common/sky_occluders.glsl) must be exactly
// the shapes the shadow rays meet, the same triangles the mesh pass draws
// (geometry/shapes.cpp): a sphere its own bounding sphere, a cube's and a
// plane's box the corners of their meshes, a capped cylinder its mesh's prism.
// Anything else (an open cylinder, a torus, a model) has no closed form.
#include "geometry/mesh.h"
#include "passes/occluders.h"
#include "scene/load.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace m3055 {
namespace {

Scene scene_of(const nlohmann::json& objects) {
    const nlohmann::json doc = {
        {"camera", {{"projection", "perspective"}, {"position", {0, 2, 6}}, {"target", {0, 0.5, 0}}, {"up", {0, 1, 0}},
                    {"fov_y_deg", 35}}},
        {"lights", {{{"type", "sky"}, {"intensity", 1.0}, {"shadow", true}}}},
        {"objects", objects}};
    return scene_from_json(doc, "sky_occluders_test.json", LoadContext::trusted());
}

const nlohmann::json kMaterial = {{"model", "lambert"}, {"kd", {0.5, 0.5, 0.5}}};

// Every corner centre +- h0 a0 +- h1 a1 +- h2 a2 of the box is a vertex of the mesh, and every
// vertex a corner (to rounding).
void expect_box_is_mesh(const SkyOccluder& box, const geometry::Mesh& mesh) {
    std::vector<dvec3> corners;
    for (int c = 0; c < 8; ++c) {
        dvec3 p = box.centre;
        for (int a = 0; a < 3; ++a) p += ((c >> a) & 1 ? 1.0 : -1.0) * box.half_sizes[a] * box.axes[a];
        corners.push_back(p);
    }
    auto near_one_of = [](const dvec3& p, const std::vector<dvec3>& points) {
        return std::any_of(points.begin(), points.end(),
                           [&](const dvec3& q) { return glm::length(p - q) < 1e-12; });
    };
    for (const dvec3& v : mesh.positions) EXPECT_TRUE(near_one_of(v, corners)) << v.x << " " << v.y << " " << v.z;
    for (const dvec3& c : corners) EXPECT_TRUE(near_one_of(c, mesh.positions)) << c.x << " " << c.y << " " << c.z;
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(glm::length(box.axes[a]), 1.0, 1e-12);
        EXPECT_NEAR(glm::dot(box.axes[a], box.axes[(a + 1) % 3]), 0.0, 1e-12);
    }
}

TEST(SkyOccluders, ASphereIsItsOwnBoundingSphere) {
    const Scene scene = scene_of(
        {{{"shape", "sphere"}, {"center", {0.5, 1.0, -2.0}}, {"radius", 0.75}, {"material", kMaterial}}});
    const OccluderTexels packed = pack_occluders(scene);
    ASSERT_EQ(packed.sky.size(), 1u);
    EXPECT_EQ(packed.sky[0].shape, SkyOccluderShape::sphere);
    EXPECT_EQ(packed.sky[0].sphere_centre, dvec3(0.5, 1.0, -2.0));
    EXPECT_EQ(packed.sky[0].radius, 0.75);
}

TEST(SkyOccluders, ACubesBoxHasItsMeshsCornersWhateverItsRotation) {
    for (const nlohmann::json& rotation : {nlohmann::json{0, 0, 0}, nlohmann::json{0, 30, 0}, nlohmann::json{17, -40, 65}}) {
        SCOPED_TRACE(rotation.dump());
        const Scene scene = scene_of({{{"shape", "cube"}, {"center", {0.9, 0.45, -0.2}}, {"size", 0.9},
                                       {"rotation_deg", rotation}, {"material", kMaterial}}});
        const OccluderTexels packed = pack_occluders(scene);
        ASSERT_EQ(packed.sky.size(), 1u);
        EXPECT_EQ(packed.sky[0].shape, SkyOccluderShape::box);
        expect_box_is_mesh(packed.sky[0], geometry::make_mesh(scene.objects[0]));
    }
}

TEST(SkyOccluders, APlaneIsABoxWithNoThickness) {
    const Scene scene = scene_of({{{"shape", "plane"}, {"center", {0, 1, -3}}, {"normal", {0.2, 0.3, 1.0}},
                                   {"size", 4}, {"material", kMaterial}}});
    const OccluderTexels packed = pack_occluders(scene);
    ASSERT_EQ(packed.sky.size(), 1u);
    EXPECT_EQ(packed.sky[0].shape, SkyOccluderShape::box);
    EXPECT_EQ(packed.sky[0].half_sizes[2], 0.0);
    expect_box_is_mesh(packed.sky[0], geometry::make_mesh(scene.objects[0]));
}

// A capped cylinder is the prism of its mesh: every rim corner
// centre +- h a + r (cos(2 pi k / n) t + sin(2 pi k / n) b) a vertex, and every vertex such a
// corner or a cap's hub (centre +- h a), whatever its axis and segments.
TEST(SkyOccluders, ACappedCylinderIsItsMeshsPrism) {
    const nlohmann::json cases[] = {{{"axis", {0, 1, 0}}, {"segments", 64}},
                                    {{"axis", {0.3, 1.0, 0.2}}, {"segments", 7}},
                                    {{"axis", {1, 0, 0}}, {"segments", 512}}};
    for (const nlohmann::json& c : cases) {
        SCOPED_TRACE(c.dump());
        const Scene scene = scene_of({{{"shape", "cylinder"}, {"center", {0.4, 0.7, -1}}, {"axis", c["axis"]},
                                       {"radius", 0.5}, {"height", 1.4}, {"segments", c["segments"]},
                                       {"material", kMaterial}}});
        const OccluderTexels packed = pack_occluders(scene);
        ASSERT_EQ(packed.sky.size(), 1u);
        const SkyOccluder& prism = packed.sky[0];
        ASSERT_EQ(prism.shape, SkyOccluderShape::prism);
        ASSERT_EQ(prism.segments, c["segments"].get<int>());
        EXPECT_EQ(frame_texel_w(prism, 0), 0.7f);
        EXPECT_EQ(frame_texel_w(prism, 1), 0.5f);
        EXPECT_EQ(frame_texel_w(prism, 2), float(prism.segments));
        std::vector<dvec3> corners;
        for (int rim = -1; rim <= 1; rim += 2) {
            const dvec3 hub = prism.centre + double(rim) * prism.half_sizes[0] * prism.axes[0];
            corners.push_back(hub);
            for (int k = 0; k < prism.segments; ++k) {
                const double angle = 2 * 3.14159265358979323846 * k / prism.segments;
                corners.push_back(hub + prism.half_sizes[1] * (std::cos(angle) * prism.axes[1] +
                                                               std::sin(angle) * prism.axes[2]));
            }
        }
        const geometry::Mesh mesh = geometry::make_mesh(scene.objects[0]);
        auto near_one_of = [](const dvec3& p, const std::vector<dvec3>& points) {
            return std::any_of(points.begin(), points.end(),
                               [&](const dvec3& q) { return glm::length(p - q) < 1e-12; });
        };
        for (const dvec3& v : mesh.positions) EXPECT_TRUE(near_one_of(v, corners)) << v.x << " " << v.y << " " << v.z;
        for (const dvec3& q : corners) EXPECT_TRUE(near_one_of(q, mesh.positions)) << q.x << " " << q.y << " " << q.z;
    }
}

TEST(SkyOccluders, AnOpenCylinderAndATorusHaveNoClosedForm) {
    const Scene scene = scene_of(
        {{{"shape", "cylinder"}, {"center", {0, 0.7, 0}}, {"axis", {0, 1, 0}}, {"radius", 0.5}, {"height", 1.4},
          {"capped", false}, {"material", kMaterial}},
         {{"shape", "torus"}, {"center", {2, 0.3, 0}}, {"axis", {0, 1, 0}}, {"major_radius", 0.6},
          {"minor_radius", 0.2}, {"material", kMaterial}}});
    const OccluderTexels packed = pack_occluders(scene);
    ASSERT_EQ(packed.sky.size(), 2u);
    for (const SkyOccluder& o : packed.sky) EXPECT_EQ(o.shape, SkyOccluderShape::other);
}

}  // namespace
}  // namespace m3055
