// The mesh shapes (plane, cube, cylinder, torus; docs/shapes.md) on the GPU
// against the CPU reference, which ray-casts the SAME triangles in double
// (reference/mesh_hits.cpp). Tolerances as for the spheres
// (gpu_vs_reference_test.cpp), on pixels at least one pixel away from a
// silhouette or a crease (coverage includes each mesh's smooth part):
//   |gpu - ref| <= 1e-3 * max(1, |ref|), >= 99.5 % of pixels on the same
//   display level, none more than one level off, no NaN or Inf.
#include "gpu_compare.h"
#include "object_builders.h"
#include "models/model_table.h"
#include "reference/reference.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <functional>
#include <ostream>

namespace m3055 {
namespace {

using test::cube;
using test::cylinder;
using test::directional;
using test::sphere;
using test::torus;

constexpr double kTolerance = 1e-3;
constexpr double kSameLevelShare = 0.995;

Material highlight(dvec3 color, double m = 10.0) {
    Material material = Material::of("highlight");
    material.set_vec3("color", color), material.set_number("m", m);
    return material;
}

Material metal() {
    Material material = Material::of("metal");
    material.set_vec3("color", {0.9, 0.6, 0.4});
    material.set_number("d", 0.05);
    material.set_lobes({{0.013, 0.2}, {0.1, 0.4}});
    return material;
}

Material blinn_phong() {
    Material material = Material::of("blinn_phong");
    material.set_vec3("kd", {0.3, 0.5, 0.8});
    material.set_vec3("ka", {0.3, 0.5, 0.8});
    material.set_number("shininess", 40);
    return material;
}

// highlight({0.2, 0.5, 0.9}) switched to the translucent model (keeps colour, d, w, m).
Material translucent(double t_n, double t_p) {
    Material material = with_model(highlight({0.2, 0.5, 0.9}), model_table().get("translucent"));
    material.set_number("t_n", t_n), material.set_number("t_p", t_p);
    return material;
}

Object plane(double y, double size, Material material) {
    Object o;
    o.shape = Shape::plane;
    o.center = {0, y, 0};
    o.axis = {0, 1, 0};
    o.size = size;
    o.material = material;
    return o;
}





std::vector<Light> key_and_fill() {
    Light point;
    point.type = LightType::point;
    point.position = {-2.0, 3.0, 2.5};
    point.color = {0.7, 0.8, 1.0};
    point.intensity = 0.8;
    return {directional({1, 1.2, 1}), point};
}

// A view from above and in front, looking at the origin.
Scene scene_with(std::vector<Object> objects, bool orthographic, std::vector<Light> lights = key_and_fill()) {
    Scene scene = test::single_sphere_scene(highlight({1, 1, 1}), lights, orthographic);
    scene.camera.position = {0.8, 2.0, 4.5};
    scene.camera.target = {0, 0, 0};
    scene.objects = std::move(objects);
    scene.background = {0.05, 0.05, 0.1};
    return scene;
}

struct Case {
    std::string name;
    std::function<Scene(bool orthographic)> make;
};
// Printed by its name (not its bytes) in test names and failure messages.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::vector<Case> all_cases() {
    std::vector<Case> cases;
    const std::vector<std::pair<std::string, Material>> materials = {
        {"highlight", highlight({0.8, 0.2, 0.2}, 20)}, {"metal", metal()}, {"blinn_phong", blinn_phong()}};
    for (const auto& [name, m] : materials) {
        const Material material = m;
        cases.push_back({"plane_" + name, [material](bool o) {
                             return scene_with({plane(-0.5, 3.0, material)}, o);
                         }});
        cases.push_back({"cube_" + name, [material](bool o) {
                             return scene_with({cube({0, 0, 0}, 1.2, {20, 35, 10}, material)}, o);
                         }});
        cases.push_back({"cylinder_" + name, [material](bool o) {
                             return scene_with({cylinder({0, 0, 0}, {0.3, 1, 0.2}, 0.6, 1.4, true, material)}, o);
                         }});
        cases.push_back({"torus_" + name, [material](bool o) {
                             return scene_with({torus({0, 0, 0}, {0.2, 1, 0.5}, 0.9, 0.3, material)}, o);
                         }});
    }
    // An open tube seen from above: its inside is back faces, so the floor shows through.
    cases.push_back({"open_cylinder_on_floor", [](bool o) {
                         return scene_with({plane(-0.7, 4.0, highlight({0.5, 0.5, 0.5}, 5)),
                                            cylinder({0, 0, 0}, {0, 1, 0}, 0.6, 1.4, false, blinn_phong())},
                                           o);
                     }});
    // A sphere resting on the floor: depth test between ray-cast sphere and mesh.
    cases.push_back({"sphere_on_floor", [](bool o) {
                         return scene_with({plane(-1.0, 6.0, highlight({0.5, 0.5, 0.5}, 5)),
                                            sphere({0, 0, 0}, 1.0, highlight({0.8, 0.2, 0.2}))},
                                           o);
                     }});
    // Everything at once, a sphere partly sunk into a cube (crossing surfaces).
    cases.push_back({"all_shapes", [](bool o) {
                         return scene_with({plane(-0.8, 6.0, highlight({0.5, 0.5, 0.5}, 5)),
                                            sphere({-1.2, -0.3, 0}, 0.5, metal()),
                                            cube({-0.2, -0.4, 0.2}, 0.8, {0, 25, 0}, blinn_phong()),
                                            sphere({-0.2, 0.1, 0.2}, 0.4, highlight({0.9, 0.9, 0.2})),
                                            cylinder({0.8, -0.3, -0.3}, {0, 1, 0}, 0.35, 1.0, true, metal()),
                                            torus({1.2, -0.6, 0.8}, {0, 1, 0}, 0.4, 0.15, highlight({0.2, 0.8, 0.3}))},
                                           o);
                     }});
    // Translucent meshes over opaque objects, and a translucent sphere over the floor.
    cases.push_back({"translucent_cube_over_sphere", [](bool o) {
                         return scene_with({sphere({0.3, 0, -1.5}, 0.8, highlight({0.9, 0.8, 0.2})),
                                            cube({-0.2, 0, 0.5}, 1.0, {10, 30, 0}, translucent(0.6, 1.0))},
                                           o);
                     }});
    cases.push_back({"translucent_sphere_over_floor", [](bool o) {
                         return scene_with({plane(-1.0, 6.0, highlight({0.5, 0.5, 0.5}, 5)),
                                            sphere({0, 0, 0}, 1.0, translucent(0.7, 1.0))},
                                           o);
                     }});
    // A torus's far side seen through its near side: triangles sorted far to near.
    cases.push_back({"translucent_torus", [](bool o) {
                         return scene_with({cube({0, 0, -2}, 1.5, {0, 0, 0}, highlight({0.9, 0.8, 0.2})),
                                            torus({0, 0, 0}, {0, 1, 0.6}, 1.0, 0.3, translucent(0.5, 0.5))},
                                           o);
                     }});
    return cases;
}

class ShapesGpuVsReference : public ::testing::TestWithParam<std::tuple<Case, bool, ShaderMode>> {};

TEST_P(ShapesGpuVsReference, MatchesWithinTolerance) {
    const Scene scene = std::get<0>(GetParam()).make(std::get<1>(GetParam()));
    const test::Comparison result = test::compare_gpu_with_reference(scene, std::get<2>(GetParam()));
    SCOPED_TRACE(result.describe());
    RecordProperty("comparison", result.describe());
    // The shapes really are on screen: a tenth of the frame or more.
    const ref::ReferenceImage reference = ref::render_reference(scene);
    long covered = 0;
    for (std::uint64_t signature : reference.coverage) covered += signature != 0;
    EXPECT_GT(covered, long(reference.coverage.size() / 10));
    EXPECT_GT(result.interior_pixels, 1000);
    EXPECT_EQ(result.nonfinite_values, 0);
    EXPECT_LE(result.max_scaled_diff, kTolerance);
    EXPECT_GE(result.same_level_share, kSameLevelShare);
    EXPECT_LE(result.max_level_diff, 1);
}

INSTANTIATE_TEST_SUITE_P(Shapes, ShapesGpuVsReference,
                         ::testing::Combine(::testing::ValuesIn(all_cases()), ::testing::Bool(),
                                            ::testing::Values(ShaderMode::specialized, ShaderMode::general)),
                         [](const auto& info) {
                             return std::get<0>(info.param).name + (std::get<1>(info.param) ? "_ortho" : "_persp") +
                                    (std::get<2>(info.param) == ShaderMode::general ? "_general" : "_specialized");
                         });

}  // namespace
}  // namespace m3055
