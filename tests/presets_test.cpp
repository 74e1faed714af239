// Light presets, the eq. 14 rescale and the default scene.
#include "scene/presets.h"

#include "scene/load.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

namespace m3055 {
namespace {

// A material of `model` with d and the lobes given.
Material metal(const char* model, double d, const std::vector<Lobe>& lobes) {
    Material material = Material::of(model);
    material.set_number("d", d);
    material.set_lobes(lobes);
    return material;
}

TEST(Eq14, PaperFig10WeightsAlreadySatisfyIt) {
    // docs/spec.md#43-metal: w = 0.013, m = 0.2 and w = 0.1, m = 0.4 give 0.95 = 1 - d, d = 0.05.
    const Material fig10 = metal("metal", 0.05, {{0.013, 0.2}, {0.1, 0.4}});
    EXPECT_NEAR(highlight_peak(fig10), 0.05 + 0.325 + 0.625, 1e-12);
    EXPECT_NEAR(highlight_peak(fig10), 1.0, 1e-12);
}

TEST(Eq14, RescaleKeepsProportionsAndMeetsOne) {
    Material material = metal("metal", 0.1, {{0.02, 0.2}, {0.3, 0.5}});
    ASSERT_TRUE(rescale_to_eq14(material));
    EXPECT_NEAR(highlight_peak(material), 1.0, 1e-12);
    const LobeList lobes = material.lobes();
    EXPECT_NEAR(lobes[0].w / lobes[1].w, 0.02 / 0.3, 1e-12);  // ratio kept
    EXPECT_EQ(lobes[0].m, 0.2);                               // roughness untouched
    EXPECT_EQ(lobes[1].m, 0.5);
    // Before: 0.1 + 0.5 + 1.2 = 1.8, so the factor is 0.9 / 1.7.
    EXPECT_NEAR(lobes[0].w, 0.02 * 0.9 / 1.7, 1e-12);
}

TEST(Eq14, ExponentLobesPeakAtTheirWeightSum) {
    const std::vector<Lobe> lobes = {{0.2, 20}, {0.8, 3}};
    EXPECT_NEAR(highlight_peak(metal("metal_phong", 0.05, lobes)), 1.05, 1e-12);
    Material blinn = metal("metal_blinn", 0.05, lobes);
    ASSERT_TRUE(rescale_to_eq14(blinn));
    EXPECT_NEAR(blinn.lobes()[0].w + blinn.lobes()[1].w, 0.95, 1e-12);
}

TEST(Eq14, ImpossibleCasesLeaveTheLobesAlone) {
    Material zero = metal("metal", 0.05, {{0.0, 0.3}});
    EXPECT_FALSE(rescale_to_eq14(zero));
    EXPECT_EQ(zero.lobes()[0].w, 0.0);
    Material full = metal("metal", 1.0, {{0.1, 0.4}});
    EXPECT_FALSE(rescale_to_eq14(full));  // d already 1
    EXPECT_EQ(full.lobes()[0].w, 0.1);
    // The roughest lobe docs/spec.md#7-scene-files allows, m = 2, needs w = (1 - d) m^2 = 4 with d = 0.
    Material rough = metal("metal", 0.0, {{0.001, 2.0}});
    ASSERT_TRUE(rescale_to_eq14(rough));
    EXPECT_NEAR(rough.lobes()[0].w, 4.0, 1e-12);
    Material highlight = Material::of("highlight");  // no lobes
    highlight.set_number("d", 0.5);
    const Material before = highlight;
    EXPECT_FALSE(rescale_to_eq14(highlight));
    EXPECT_EQ(highlight, before);
}

TEST(LightPresets, NamesRoundTrip) {
    for (LightPreset p : kAllLightPresets) {
        LightPreset parsed;
        ASSERT_TRUE(parse_light_preset(preset_name(p), &parsed));
        EXPECT_EQ(parsed, p);
    }
    LightPreset unused;
    EXPECT_FALSE(parse_light_preset("four_point", &unused));
}

TEST(LightPresets, SingleKeyIsUpperRightFront) {
    const auto lights = light_preset(LightPreset::single_key);
    ASSERT_EQ(lights.size(), 1u);
    EXPECT_GT(lights[0].direction.x, 0.0);
    EXPECT_GT(lights[0].direction.y, 0.0);
    EXPECT_GT(lights[0].direction.z, 0.0);
}

TEST(LightPresets, ThreePointHasKeyFillAndBack) {
    for (LightPreset p : {LightPreset::three_point_white, LightPreset::three_point_warm,
                          LightPreset::three_point_cool}) {
        const auto lights = light_preset(p);
        ASSERT_EQ(lights.size(), 3u);
        const Light &key = lights[0], &fill = lights[1], &back = lights[2];
        EXPECT_GT(key.direction.x, 0.0);    // key on one side...
        EXPECT_LT(fill.direction.x, 0.0);   // ...fill on the other
        EXPECT_LT(back.direction.z, 0.0);   // back light behind the object
        EXPECT_GT(back.direction.y, 0.0);   // and above it
        EXPECT_GT(key.intensity, fill.intensity);  // fill is weaker than the key
        for (const Light& l : lights) EXPECT_NEAR(glm::length(l.direction), 1.0, 1e-12);
        EXPECT_EQ(fill.color, dvec3(1.0));
        EXPECT_EQ(back.color, dvec3(1.0));
    }
    const dvec3 warm = light_preset(LightPreset::three_point_warm)[0].color;
    const dvec3 cool = light_preset(LightPreset::three_point_cool)[0].color;
    EXPECT_EQ(light_preset(LightPreset::three_point_white)[0].color, dvec3(1.0));
    EXPECT_GT(warm.r, warm.b);  // warm: more red than blue
    EXPECT_GT(cool.b, cool.r);  // cool: more blue than red
}

TEST(LightPresets, PaperSecondaryIsLeftBelowAndWeaker) {
    const auto lights = light_preset(LightPreset::paper_main_secondary);
    ASSERT_EQ(lights.size(), 2u);
    EXPECT_GT(lights[0].direction.x, 0.0);
    EXPECT_GT(lights[0].direction.y, 0.0);
    EXPECT_EQ(lights[0].intensity, 1.0);
    EXPECT_LT(lights[1].direction.x, 0.0);
    EXPECT_LT(lights[1].direction.y, 0.0);
    EXPECT_GT(lights[1].direction.z, 0.0);  // still in front: it lights the visible side
    EXPECT_EQ(lights[1].intensity, 0.7);
}

TEST(LightPresets, EveryPresetMakesAValidScene) {
    for (LightPreset p : kAllLightPresets) {
        Scene scene = default_scene();
        scene.lights = light_preset(p);
        EXPECT_NO_THROW(
            scene_from_json(scene_to_json(scene, PathWriting::absolute()), "preset.json", LoadContext::trusted()))
            << preset_name(p);
    }
}

// The defaults come from the model table (models/builtin_models.cpp).
TEST(DefaultLobes, MetalDefaultsMeetEq14WithThePapersD) {
    for (const char* model : {"metal", "metal_blinn"}) {
        Material material = Material::of(model);
        material.set_number("d", 0.05);
        EXPECT_NEAR(highlight_peak(material), 1.0, 1e-12) << model;
    }
    EXPECT_FALSE(Material::of("highlight").has("lobes"));
}

TEST(DefaultScene, IsTheSpecExample) {
    const Scene scene = default_scene();
    EXPECT_EQ(scene.display.width, 512);
    EXPECT_EQ(scene.display.height, 320);
    EXPECT_EQ(scene.display.bits, 5);
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].material.model_name(), "highlight");
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_NEAR(scene.lights[0].direction.x, 1.0 / std::sqrt(3.0), 1e-12);
}

}  // namespace
}  // namespace m3055
