// Measured metals (docs/spec.md#72-measured-metals) — the paper's metals and
// microfacet with each of its Fresnel choices — and colour spectra (the paper's
// color_spectrum, the classic models' kd_spectrum) on the GPU against the CPU
// reference, which sums every (conductor, light) pair per wavelength at the
// pixel's exact V.H (reference/conductor.h) where the GPU reads its precomputed
// tables (passes/spectral_tables.h: F(lambda, 0), or 65 samples over cos theta
// linearly interpolated when F depends on the angle). Tolerances, on pixels at least
// one pixel away from a silhouette, as tests/gpu_vs_reference_test.cpp's:
//   |gpu - ref| <= 1e-3 * max(1, |ref|) on the unquantized colour,
//   >= 99.5 % of pixels on the same display level, none more than one level off,
//   and no NaN or Inf anywhere.
#include "gpu_compare.h"

#include "models/model_table.h"
#include "scene/light_colour.h"

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
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

Material conductor(const char* model, const char* metal, const char* fresnel, std::vector<Lobe> lobes) {
    Material material = Material::of(model);
    material.set_choice("conductor", metal);
    material.set_choice("fresnel", fresnel);
    material.set_number("d", 0.05);
    material.set_lobes(lobes);
    return material;
}

Light kelvin(Light light, double k) {
    std::string error;
    EXPECT_TRUE(set_temperature(light, k, &error)) << error;
    return light;
}

Light illuminant(Light light, const char* name) {
    std::string error;
    EXPECT_TRUE(set_illuminant(light, name, &error)) << error;
    return light;
}

// RGB lights (which stand for D65 scaled by their colour), a studio rig of
// black bodies with a CIE A point light, and a light at grazing incidence.
std::vector<std::pair<std::string, std::vector<Light>>> light_setups() {
    Light back;
    back.type = LightType::point;
    back.position = {0.5, 2.5, -2.0};
    back.intensity = 2.0;
    back.att_constant = 0.5, back.att_linear = 0.2, back.att_quadratic = 0.05;
    Light spot;
    spot.type = LightType::spot;
    spot.position = {-2.0, 2.0, 3.0};
    spot.spot_direction = -glm::normalize(spot.position);
    spot.spot_exponent = 8;
    spot.color = {1.0, 0.6, 0.6};
    return {
        {"rgb", {directional({1, 1, 1}), directional({-1, -0.6, 0.6}, 0.7, {0.7, 0.8, 1.0})}},
        {"studio",
         {kelvin(directional({1, 1, 1}), 3200), kelvin(directional({-1, -0.6, 0.6}, 0.7), 5600),
          illuminant(back, "A"), spot}},
        {"grazing", {kelvin(directional({1, 0, 0.05}), 2000), illuminant(directional({0, 1, 0.2}), "F11")}},
    };
}

std::vector<Case> all_cases() {
    const std::vector<std::pair<std::string, Material>> materials = {
        {"gold_normal", conductor("metal", "gold", "normal", {{0.013, 0.2}, {0.1, 0.4}})},
        {"gold_full", conductor("metal", "gold", "full", {{0.013, 0.2}, {0.1, 0.4}})},
        {"copper_full_rough", conductor("metal", "copper", "full", {{0.9, 0.6}})},
        {"silver_full_blinn", conductor("metal_blinn", "silver", "full", {{0.95, 13}})},
        {"aluminium_normal_phong", conductor("metal_phong", "aluminium", "normal", {{0.2, 20}, {0.75, 3}})},
        {"iron_full_phong", conductor("metal_phong", "iron", "full", {{0.95, 5}})},
    };
    std::vector<Material> microfacets;
    for (const char* fresnel : {"none", "schlick", "dielectric"}) {
        Material m = Material::of("microfacet");
        m.set_choice("conductor", "gold");
        m.set_choice("fresnel", fresnel);
        m.set_vec3("kd", {0.05, 0.04, 0.03});
        m.set_lobes({{0.7, 0.25}, {0.3, 0.6}});
        microfacets.push_back(m);
    }
    Material ggx = microfacets[2];
    ggx.set_choice("distribution", "ggx");
    ggx.set_choice("conductor", "titanium");
    // Colour spectra (docs/spec.md#73-spectral-colours): one C0 per light, on a highlight and a metal.
    ReflectanceSpectrum rising;
    rising.nm = {380, 480, 560, 620, 780}, rising.values = {0.05, 0.1, 0.5, 0.85, 0.9};
    Material spectral_highlight = Material::of("highlight");
    spectral_highlight.set_colour_spectrum(&rising);
    Material spectral_translucent = with_model(spectral_highlight, model_table().get("translucent"));
    Material spectral_metal = conductor("metal", "none", "normal", {{0.013, 0.2}, {0.1, 0.4}});
    spectral_metal.set_colour_spectrum(&rising);
    std::vector<std::pair<std::string, Material>> all = materials;
    all.push_back({"spectrum_highlight", spectral_highlight});
    all.push_back({"spectrum_translucent", spectral_translucent});
    all.push_back({"spectrum_metal", spectral_metal});
    all.push_back({"microfacet_gold_none", microfacets[0]});
    all.push_back({"microfacet_gold_schlick", microfacets[1]});
    all.push_back({"microfacet_gold_dielectric", microfacets[2]});
    all.push_back({"microfacet_titanium_ggx", ggx});
    // kd as a spectrum on the classic models (one colour per light), alone and under a microfacet conductor.
    Material kd_lambert = Material::of("lambert");
    kd_lambert.set_colour_spectrum(&rising);
    Material kd_phong = with_model(kd_lambert, model_table().get("phong"));
    kd_phong.set_number("shininess", 40);
    Material kd_oren_nayar = with_model(kd_lambert, model_table().get("oren_nayar"));
    Material kd_gold = microfacets[2];
    kd_gold.set_colour_spectrum(&rising);
    all.push_back({"kd_spectrum_lambert", kd_lambert});
    all.push_back({"kd_spectrum_phong", kd_phong});
    all.push_back({"kd_spectrum_oren_nayar", kd_oren_nayar});
    all.push_back({"kd_spectrum_microfacet_gold_dielectric", kd_gold});
    // The combined case first, then material-major with six (light set-up,
    // camera) cases per material: the sanitizer tree's every fifth case
    // (tests/CMakeLists.txt) then has the combined case, every material and,
    // 5 being prime to 6, every light set-up and camera.
    std::vector<Case> cases;
    // Two conductors and a colour metal in one frame: each record finds its own table.
    cases.push_back({"three_metals", [] {
        Scene scene = test::single_sphere_scene(conductor("metal", "copper", "full", {{0.1, 0.3}}),
                                                {kelvin(directional({1, 1, 1}), 3200)}, false);
        scene.objects[0].center = {-0.9, 0, 0}, scene.objects[0].radius = 0.6;
        Object gold = scene.objects[0];
        gold.center = {0.9, 0, 0};
        gold.material = conductor("metal_blinn", "gold", "normal", {{0.9, 20}});
        Object plain = scene.objects[0];
        plain.center = {0, 0.9, -0.5};
        plain.material = Material::of("metal");
        scene.objects.push_back(gold);
        scene.objects.push_back(plain);
        return scene;
    }});
    for (const auto& [material_name, material] : all)
        for (const auto& [light_name, lights] : light_setups())
            for (bool ortho : {false, true}) {
                Material m = material;
                auto l = lights;
                cases.push_back({material_name + "_" + light_name + (ortho ? "_ortho" : "_persp"),
                                 [m, l, ortho]() { return test::single_sphere_scene(m, l, ortho); }});
            }
    return cases;
}

// Each case in both shader modes against one reference (the spectral reference
// is most of a case's time).
class ConductorGpuVsReference : public ::testing::TestWithParam<Case> {};

TEST_P(ConductorGpuVsReference, MatchesWithinToleranceInBothShaderModes) {
    const Scene scene = GetParam().make();
    const std::vector<ShaderMode> modes = {ShaderMode::specialized, ShaderMode::general};
    const std::vector<test::Comparison> results = test::compare_gpu_modes_with_reference(scene, modes);
    for (std::size_t i = 0; i < modes.size(); ++i) {
        const test::Comparison& result = results[i];
        SCOPED_TRACE(std::string(modes[i] == ShaderMode::general ? "general" : "specialized") + " shaders: " +
                     result.describe());
        RecordProperty(modes[i] == ShaderMode::general ? "general" : "specialized", result.describe());
        EXPECT_GT(result.interior_pixels, 1000);
        EXPECT_EQ(result.nonfinite_values, 0);
        EXPECT_LE(result.max_scaled_diff, kTolerance);
        EXPECT_GE(result.same_level_share, kSameLevelShare);
        EXPECT_LE(result.max_level_diff, 1);
    }
}

INSTANTIATE_TEST_SUITE_P(Conductors, ConductorGpuVsReference, ::testing::ValuesIn(all_cases()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace m3055
