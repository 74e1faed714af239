// The GLSL classic models (docs/spec.md#5-classic-models) against the double-precision reference,
// with the tolerances of the paper's models (tests/gpu_vs_reference_test.cpp),
// on pixels at least one pixel from a silhouette:
//   |gpu - ref| <= 1e-3 * max(1, |ref|) on the unquantized colour,
//   >= 99.5 % of pixels on the same display level, none more than one level off,
//   no NaN or Inf anywhere.
// Every model at typical and edge parameters (exponents 0 and 10000, roughness
// 0.001 and the top of its range, IOR 1 and 5, 4-lobe mixtures, a tangent axis
// whose pole is in view), under four light set-ups (one of them with point and
// spot lights, attenuation, per-light and global ambient), both cameras, and
// specialized and general programs.
#include "gpu_compare.h"

#include "reference/classic.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <functional>
#include <ostream>

namespace m3055 {
namespace {

using test::directional;

constexpr double kTolerance = 1e-3;
constexpr double kSameLevelShare = 0.995;

using ref::Distribution;
using ref::Fresnel;

Material classic(const char* model) {
    Material material = Material::of(model);
    material.set_vec3("kd", {0.7, 0.3, 0.2});
    material.set_vec3("ka", {0.7, 0.3, 0.2});
    if (material.has("ks")) material.set_vec3("ks", {0.9, 0.9, 1.0});
    return material;
}

Material with_shininess(const char* model, double n) {
    Material material = classic(model);
    material.set_number("shininess", n);
    return material;
}

Material oren_nayar(double sigma) {
    Material material = classic("oren_nayar");
    material.set_number("sigma", sigma);
    return material;
}

Material microfacet(Distribution distribution, std::vector<Lobe> lobes, Fresnel fresnel = Fresnel::schlick,
                    double ior = 1.5) {
    Material material = classic("microfacet");
    material.set_vec3("kd", {0.2, 0.1, 0.05});
    material.set_choice("distribution", int(distribution));
    material.set_lobes(lobes);
    material.set_choice("fresnel", int(fresnel));
    material.set_number("ior", ior);
    return material;
}

Material ward(double ax, double ay, dvec3 axis = {0, 1, 0}) {
    Material material = classic("ward");
    material.set_vec3("kd", {0.1, 0.1, 0.2});
    material.set_number("alpha_x", ax), material.set_number("alpha_y", ay);
    material.set_vec3("axis", glm::normalize(axis));
    return material;
}

Material heidrich_seidel(double n, dvec3 axis = {0, 1, 0}) {
    Material material = with_shininess("heidrich_seidel", n);
    material.set_vec3("kd", {0.1, 0.2, 0.1});
    material.set_vec3("axis", glm::normalize(axis));
    return material;
}

// K_spec scaled down: a narrow lobe's peak (250 for Ward at 0.001 x 1) brought
// to displayable values, as the paper's test weights its m = 0.001 lobe by 1e-6.
Material dim(Material material, double ks) {
    material.set_vec3("ks", dvec3(ks));
    return material;
}

Material minnaert(double k) {
    Material material = classic("minnaert");
    material.set_number("minnaert_k", k);
    return material;
}

// Burley's principled BRDF with `numbers` set (the rest at disney.brdf's defaults).
Material principled(std::vector<std::pair<const char*, double>> numbers, dvec3 base = {0.7, 0.3, 0.2},
                    dvec3 axis = {0, 1, 0}) {
    Material material = Material::of("principled");
    material.set_vec3("base_color", base);
    material.set_vec3("ka", base);
    material.set_vec3("axis", glm::normalize(axis));
    for (const auto& [name, value] : numbers) material.set_number(name, value);
    return material;
}

std::vector<std::pair<std::string, Material>> materials() {
    Material glowing = classic("blinn_phong");
    glowing.set_vec3("emission", {0.1, 0.05, 0.0});
    glowing.set_vec3("ka", {0.3, 0.6, 0.9});
    return {
        {"lambert", classic("lambert")},
        {"half_lambert", classic("half_lambert")},
        {"half_lambert_clamped", classic("half_lambert_clamped")},
        {"half_lambert_normalized", classic("half_lambert_normalized")},
        {"oren_nayar", oren_nayar(0.5)},
        {"oren_nayar_s0", oren_nayar(0.0)},
        {"oren_nayar_s10", oren_nayar(10.0)},
        {"minnaert", classic("minnaert")},
        {"minnaert_k05", minnaert(0.5)},
        {"minnaert_k15", minnaert(1.5)},
        {"phong", with_shininess("phong", 32)},
        {"phong_n0", with_shininess("phong", 0)},
        {"phong_n10000", with_shininess("phong", 10000)},
        {"blinn_phong", with_shininess("blinn_phong", 32)},
        {"blinn_phong_n10000", with_shininess("blinn_phong", 10000)},
        {"blinn_phong_emission_ambient", glowing},
        {"mf_blinn_phong", microfacet(Distribution::blinn_phong, {{1, 50}})},
        {"mf_blinn_phong_n0_n10000", microfacet(Distribution::blinn_phong, {{0.5, 0}, {0.5, 10000}}, Fresnel::none)},
        {"mf_gaussian", microfacet(Distribution::gaussian, {{1, 0.2}})},
        // Roughness 0.001 with a tiny weight, as the paper's test does for metal m = 0.001:
        // the lobe's peak stays displayable; full weight: NarrowLobes below.
        {"mf_gaussian_m0001_m2", microfacet(Distribution::gaussian, {{1e-6, 0.001}, {0.7, 2}}, Fresnel::none)},
        {"mf_beckmann", microfacet(Distribution::beckmann, {{1, 0.3}}, Fresnel::dielectric)},
        {"mf_beckmann_m0001", microfacet(Distribution::beckmann, {{1e-6, 0.001}, {0.5, 0.3}}, Fresnel::none)},
        {"mf_beckmann_4_lobes", microfacet(Distribution::beckmann, {{0.4, 0.05}, {0.3, 0.2}, {0.2, 0.5}, {0.1, 2}})},
        {"mf_ggx", microfacet(Distribution::ggx, {{1, 0.25}}, Fresnel::dielectric, 1.5)},
        {"mf_ggx_m0001_ior5", microfacet(Distribution::ggx, {{1, 0.001}}, Fresnel::dielectric, 5.0)},
        {"mf_ggx_m2_ior1", microfacet(Distribution::ggx, {{1, 2}}, Fresnel::dielectric, 1.0)},
        {"mf_ggx_two_lobes", microfacet(Distribution::ggx, {{0.7, 0.1}, {0.3, 0.6}}, Fresnel::schlick, 2.0)},
        {"ward", ward(0.15, 0.5)},
        {"ward_a0001_a1", dim(ward(0.001, 1.0), 2e-3)},
        {"ward_tilted_axis", ward(0.1, 0.4, {0, 1, 1})},
        {"heidrich_seidel", heidrich_seidel(32)},
        {"heidrich_seidel_n10000", heidrich_seidel(10000)},
        {"heidrich_seidel_tilted_axis", heidrich_seidel(20, {1, 1, 1})},
        {"principled", principled({})},
        {"principled_r1", principled({{"roughness", 1}})},
        {"principled_metallic", principled({{"metallic", 1}, {"roughness", 0.3}}, {0.9, 0.6, 0.2})},
        {"principled_anisotropic_tilted_axis", principled({{"anisotropic", 1}, {"roughness", 0.5}}, {0.3, 0.3, 0.8},
                                                          {0, 1, 1})},
        {"principled_clearcoat_gloss05", principled({{"clearcoat", 1}, {"clearcoat_gloss", 0.5}}, {0.1, 0.2, 0.6})},
        // Its narrowest lobes at full weight hold the main bound (measured worst 4.0e-4, roughness 0):
        // GTR2 and GTR1 are written without 1 - cos^2 (glsl/models/principled.glsl).
        {"principled_r0", principled({{"roughness", 0}})},  // GTR2 alpha 0.001
        {"principled_r0_anisotropic", principled({{"roughness", 0}, {"anisotropic", 1}})},
        {"principled_clearcoat_gloss1", principled({{"clearcoat", 1}, {"clearcoat_gloss", 1}})},  // GTR1 alpha 0.001
        {"principled_sheen_tinted", principled({{"sheen", 1}, {"sheen_tint", 1}, {"roughness", 0.9}}, {0.5, 0.1, 0.1})},
        {"principled_subsurface", principled({{"subsurface", 1}, {"roughness", 1}})},
        {"principled_specular_tint", principled({{"specular", 1}, {"specular_tint", 1}, {"roughness", 0.25}},
                                                {0.2, 0.5, 0.8})},
        {"principled_black_all_on", principled({{"subsurface", 0.5}, {"metallic", 0.5}, {"specular_tint", 0.5},
                                                {"roughness", 0.4}, {"anisotropic", 0.5}, {"sheen", 0.7},
                                                {"clearcoat", 0.5}, {"clearcoat_gloss", 0.3}},
                                               {0, 0, 0}, {1, 1, 0})},
    };
}

// The light set-ups of the paper's GPU test, the three-point one with the
// lecture's per-light ambient and a global ambient.
struct Setup {
    std::string name;
    std::vector<Light> lights;
    dvec3 global_ambient{0.0};
};

std::vector<Setup> light_setups() {
    Light key = directional({1, 1, 1});
    key.ambient = {0.05, 0.05, 0.05};
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
    spot.ambient = {0.2, 0.1, 0.1};
    return {
        {"key", {directional({1, 1, 1})}, dvec3(0.0)},
        {"three_point", {key, fill, back, spot}, dvec3(0.1, 0.1, 0.12)},
        {"behind", {directional({0, 0, -1})}, dvec3(0.0)},
        {"at_90_degrees", {directional({1, 0, 0})}, dvec3(0.0)},
    };
}

struct Case {
    std::string name;
    std::function<Scene()> make;
};
// Printed by its name (not its bytes) in test names and failure messages.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::vector<Case> all_cases() {
    std::vector<Case> cases;
    for (const Setup& setup : light_setups()) {
        for (const auto& [material_name, material] : materials()) {
            for (bool ortho : {false, true}) {
                const Material m = material;
                const Setup s = setup;
                cases.push_back({material_name + "_" + setup.name + (ortho ? "_ortho" : "_persp"), [m, s, ortho] {
                                     Scene scene = test::single_sphere_scene(m, s.lights, ortho);
                                     scene.ambient = s.global_ambient;
                                     return scene;
                                 }});
            }
        }
    }
    // Every classic model next to the paper's, in one program: the dispatch.
    cases.push_back({"classic_and_paper_models_together", [] {
        Scene scene = test::single_sphere_scene(classic("oren_nayar"), light_setups()[1].lights, false);
        scene.ambient = {0.1, 0.1, 0.1};
        const auto all = materials();
        scene.objects.clear();
        for (std::size_t i = 0; i < all.size(); ++i) {
            Object object;
            object.center = {-2.0 + 0.8 * double(i % 6), 1.2 - 0.8 * double(i / 6), -1.0};
            object.radius = 0.35;
            object.material = all[i].second;
            scene.objects.push_back(object);
        }
        Object paper;
        paper.center = {1.6, -1.0, 0.0};
        paper.radius = 0.4;
        paper.material = Material::of("metal");
        paper.material.set_vec3("color", {0.9, 0.6, 0.4});
        paper.material.set_number("d", 0.05);
        paper.material.set_lobes({{0.013, 0.2}, {0.1, 0.4}});
        scene.objects.push_back(paper);
        return scene;
    }});
    return cases;
}

// Narrow lobes at full weight (roughness 0.001, peaks of 1e4 to 1e5). The
// float hit point carries ~1e-7 of relative error, so N, V, L and with them
// theta_h are off by a few 1e-7 rad; a lobe of width m magnifies that by
// 2 theta_h / m^2 in exp(-(theta_h/m)^2): ~1e-3 relative near theta_h = 2m for
// m = 0.001, more where h.N is small (Ward). These cases hold a stated looser
// bound on the scaled difference;
// the level checks and no-NaN checks are unchanged.
constexpr double kNarrowLobeTolerance = 1e-2;  // measured worst: 7.6e-3, Ward 0.001 x 1, light at 90 deg

std::vector<Case> narrow_lobe_cases() {
    const std::vector<std::pair<std::string, Material>> narrow = {
        {"mf_beckmann_m0001", microfacet(Distribution::beckmann, {{1, 0.001}}, Fresnel::none)},
        {"mf_gaussian_m0001", microfacet(Distribution::gaussian, {{1, 0.001}}, Fresnel::none)},
        {"mf_ggx_m0001", microfacet(Distribution::ggx, {{1, 0.001}}, Fresnel::none)},
        {"mf_blinn_phong_n10000", microfacet(Distribution::blinn_phong, {{1, 10000}}, Fresnel::none)},
        {"ward_a0001", ward(0.001, 0.001)},
        {"ward_a0001_a1", ward(0.001, 1.0)},
    };
    std::vector<Case> cases;
    for (const Setup& setup : light_setups()) {
        for (const auto& [material_name, material] : narrow) {
            const Material m = material;
            const Setup s = setup;
            cases.push_back({material_name + "_" + setup.name, [m, s] {
                                 Scene scene = test::single_sphere_scene(m, s.lights, false);
                                 scene.ambient = s.global_ambient;
                                 return scene;
                             }});
        }
    }
    return cases;
}

class NarrowLobes : public ::testing::TestWithParam<Case> {};

TEST_P(NarrowLobes, MatchWithinTheStatedBound) {
    const test::Comparison result = test::compare_gpu_with_reference(GetParam().make());
    SCOPED_TRACE(result.describe());
    RecordProperty("comparison", result.describe());
    std::printf("[ result   ] %s\n", result.describe().c_str());
    EXPECT_GT(result.interior_pixels, 1000);
    EXPECT_EQ(result.nonfinite_values, 0);
    EXPECT_LE(result.max_scaled_diff, kNarrowLobeTolerance);
    EXPECT_GE(result.same_level_share, kSameLevelShare);
    EXPECT_LE(result.max_level_diff, 1);
}

INSTANTIATE_TEST_SUITE_P(ClassicModels, NarrowLobes, ::testing::ValuesIn(narrow_lobe_cases()),
                         [](const auto& info) { return info.param.name; });

class ClassicGpuVsReference : public ::testing::TestWithParam<std::tuple<Case, ShaderMode>> {};

TEST_P(ClassicGpuVsReference, MatchesWithinTolerance) {
    const Scene scene = std::get<0>(GetParam()).make();
    const test::Comparison result = test::compare_gpu_with_reference(scene, std::get<1>(GetParam()));
    SCOPED_TRACE(result.describe());
    RecordProperty("comparison", result.describe());
    std::printf("[ result   ] %s\n", result.describe().c_str());
    EXPECT_GT(result.interior_pixels, 1000);
    EXPECT_EQ(result.nonfinite_values, 0);
    EXPECT_LE(result.max_scaled_diff, kTolerance);
    EXPECT_GE(result.same_level_share, kSameLevelShare);
    EXPECT_LE(result.max_level_diff, 1);
}

INSTANTIATE_TEST_SUITE_P(ClassicModels, ClassicGpuVsReference,
                         ::testing::Combine(::testing::ValuesIn(all_cases()),
                                            ::testing::Values(ShaderMode::specialized, ShaderMode::general)),
                         [](const auto& info) {
                             return std::get<0>(info.param).name +
                                    (std::get<1>(info.param) == ShaderMode::general ? "_general" : "_specialized");
                         });

}  // namespace
}  // namespace m3055
