// The GLSL path (llvmpipe, float) against the double-precision CPU reference,
// for every model of docs/spec.md#4-paper-models, several light set-ups, both cameras and the edge
// parameters. Tolerances, on pixels at least one pixel away from a
// silhouette:
//   |gpu - ref| <= 1e-3 * max(1, |ref|) on the unquantized colour (absolute
//     1e-3 for displayable values; relative above 1, where metals with narrow
//     Beckmann lobes reach 1e6 and the display clamps anyway),
//   >= 99.5 % of pixels on the same display level, none more than one level off,
//   and no NaN or Inf anywhere.
#include "gpu_compare.h"

#include "models/model_table.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <functional>
#include <ostream>

namespace m3055 {
namespace {

using test::directional;

constexpr double kTolerance = 1e-3;
constexpr double kSameLevelShare = 0.995;

struct Case {
    std::string name;
    std::function<Scene()> make;
};
// Printed by its name (not its bytes) in test names and failure messages.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

Material highlight(double m, double w = 1.0, double d = 0.5, dvec3 color = {0.8, 0.2, 0.2}) {
    Material material = Material::of("highlight");
    material.set_vec3("color", color), material.set_number("m", m), material.set_number("w", w);
    material.set_number("d", d);
    return material;
}

// highlight(10) switched to the translucent model (keeps d, w, m).
Material translucent(double t_n, double t_p) {
    Material material = with_model(highlight(10), model_table().get("translucent"));
    material.set_vec3("color", {0.2, 0.5, 0.9});
    material.set_number("t_n", t_n), material.set_number("t_p", t_p);
    return material;
}

Material metal(const char* model, std::vector<Lobe> lobes, double d = 0.05) {
    Material material = Material::of(model);
    material.set_vec3("color", {0.9, 0.6, 0.4});
    material.set_number("d", d);
    material.set_lobes(lobes);
    return material;
}

// Light set-ups: the paper's single light, a three-point rig with coloured,
// point and spot lights, a light exactly behind, and one at 90 degrees to the view.
std::vector<std::pair<std::string, std::vector<Light>>> light_setups() {
    Light key = directional({1, 1, 1});
    Light fill = directional({-1, -0.6, 0.6}, 0.7, {0.7, 0.8, 1.0});
    Light back;
    back.type = LightType::point;
    back.position = {0.5, 2.5, -2.0};
    back.intensity = 2.0;
    back.color = {1.0, 0.9, 0.6};
    back.att_constant = 0.5, back.att_linear = 0.2, back.att_quadratic = 0.05;
    Light spot;
    spot.type = LightType::spot;
    spot.position = {-2.0, 2.0, 3.0};
    spot.spot_direction = -glm::normalize(spot.position);
    spot.spot_exponent = 8;
    spot.color = {1.0, 0.6, 0.6};
    return {
        {"key", {key}},
        {"three_point", {key, fill, back, spot}},
        {"behind", {directional({0, 0, -1})}},
        {"at_90_degrees", {directional({1, 0, 0})}},
    };
}

std::vector<Case> all_cases() {
    std::vector<std::pair<std::string, Material>> materials = {
        {"highlight_m10", highlight(10)},
        {"highlight_m0", highlight(0)},
        {"highlight_m10000", highlight(10000)},
        {"highlight_w0_d0", highlight(20, 0.0, 0.0, {0.3, 0.9, 0.4})},
        {"translucent", translucent(0.7, 1.0)},
        {"translucent_tp0", translucent(0.6, 0.0)},
        {"translucent_tp10", translucent(0.9, 10.0)},
        {"metal_fig10", metal("metal", {{0.013, 0.2}, {0.1, 0.4}})},
        {"metal_m0001", metal("metal", {{1e-6, 0.001}, {0.1, 0.4}})},
        {"metal_m2", metal("metal", {{3.0, 2.0}})},
        {"metal_blinn", metal("metal_blinn", {{0.95, 13}})},
        {"metal_blinn_n10000", metal("metal_blinn", {{0.5, 10000}, {0.45, 0}})},
        {"metal_phong", metal("metal_phong", {{0.2, 20}, {0.8, 3}})},
        {"metal_phong_n0", metal("metal_phong", {{0.5, 0}})},
    };
    std::vector<Case> cases;
    for (const auto& [light_name, lights] : light_setups()) {
        for (const auto& [material_name, material] : materials) {
            for (bool ortho : {false, true}) {
                Material m = material;
                auto l = lights;
                cases.push_back({material_name + "_" + light_name + (ortho ? "_ortho" : "_persp"),
                                 [m, l, ortho]() { return test::single_sphere_scene(m, l, ortho); }});
            }
        }
    }
    // Per-light lobes (the paper's Fig. 11): the secondary light uses its own lobe.
    cases.push_back({"metal_per_light_lobes", [] {
        Light main = directional({1, 1, 1});
        Light secondary = directional({-1, -0.6, 0.6}, 0.7);
        secondary.lobes = {{0.01, 0.4}};
        secondary.lobe_kind = LobeKind::beckmann;
        return test::single_sphere_scene(metal("metal", {{0.013, 0.2}, {0.1, 0.4}}), {main, secondary}, false);
    }});
    // Fig. 9: an opaque sphere behind a translucent one, on a grey background.
    cases.push_back({"translucent_over_opaque", [] {
        Scene scene = test::single_sphere_scene(translucent(0.8, 1.0), {directional({1, 1, 1})}, false);
        scene.background = {0.1, 0.1, 0.1};
        scene.objects[0].center = {-0.5, 0, 0.4};
        scene.objects[0].radius = 0.9;
        Object back;
        back.center = {0.7, 0.1, -1.2};
        back.material = highlight(20, 1, 0.5, {0.9, 0.8, 0.2});
        scene.objects.push_back(back);
        return scene;
    }});
    // Three translucent spheres in a row, composited back to front, over a metal.
    cases.push_back({"translucent_stack", [] {
        Scene scene = test::single_sphere_scene(metal("metal_blinn", {{0.95, 13}}),
                                                {directional({1, 1, 1}), directional({-1, 0.2, 0.5}, 0.5)}, false);
        scene.objects[0].center = {0, 0, -3};
        for (int i = 0; i < 3; ++i) {
            Object glass;
            glass.center = {-0.9 + 0.9 * i, 0.2 * i, -1.0 + 0.8 * i};
            glass.radius = 0.5;
            glass.material = translucent(0.3 + 0.2 * i, 1.0);
            scene.objects.push_back(glass);
        }
        return scene;
    }});
    return cases;
}

class GpuVsReference : public ::testing::TestWithParam<std::tuple<Case, ShaderMode>> {};

// Specialized programs (per scene shape) and the general program must both match.
TEST_P(GpuVsReference, MatchesWithinTolerance) {
    const Scene scene = std::get<0>(GetParam()).make();
    const test::Comparison result = test::compare_gpu_with_reference(scene, std::get<1>(GetParam()));
    SCOPED_TRACE(result.describe());
    RecordProperty("comparison", result.describe());
    EXPECT_GT(result.interior_pixels, 1000);
    EXPECT_EQ(result.nonfinite_values, 0);
    EXPECT_LE(result.max_scaled_diff, kTolerance);
    EXPECT_GE(result.same_level_share, kSameLevelShare);
    EXPECT_LE(result.max_level_diff, 1);
}

INSTANTIATE_TEST_SUITE_P(AllModels, GpuVsReference,
                         ::testing::Combine(::testing::ValuesIn(all_cases()),
                                            ::testing::Values(ShaderMode::specialized, ShaderMode::general)),
                         [](const auto& info) {
                             return std::get<0>(info.param).name +
                                    (std::get<1>(info.param) == ShaderMode::general ? "_general" : "_specialized");
                         });

}  // namespace
}  // namespace m3055
