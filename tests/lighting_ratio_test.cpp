// The key-to-fill ratio (renderer/analysis/lighting_ratio.h) and light names
// in scene files: what three-point lessons and grading rules are built on.
#include "analysis/lighting_ratio.h"
#include "scene/load.h"
#include "scene/presets.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <stdexcept>

namespace m3055 {
namespace {

using nlohmann::json;

Scene with_lights(std::vector<Light> lights) {
    Scene scene = default_scene();
    scene.lights = std::move(lights);
    return scene;
}

Light named(const std::string& name, double intensity, dvec3 color = dvec3(1.0)) {
    Light light;
    light.name = name;
    light.intensity = intensity;
    light.color = color;
    return light;
}

TEST(KeyToFillRatio, IsTheKeysIlluminanceOverTheFills) {
    const KeyFillRatio r = key_to_fill_ratio(with_lights({named("fill", 0.25), named("key", 1.0)}));
    ASSERT_TRUE(r.ok()) << r.problem;
    EXPECT_EQ(r.key, 1);
    EXPECT_EQ(r.fill, 0);
    EXPECT_DOUBLE_EQ(r.ratio, 4.0);
    EXPECT_DOUBLE_EQ(r.stops, 2.0);
    EXPECT_EQ(r.text(), "4.00:1 (2.00 stops)");
}

TEST(KeyToFillRatio, WeighsColoursByLuminanceAndPointLightsByDistance) {
    // A pure blue fill carries 0.0722 of white's luminance (Rec. 709).
    const KeyFillRatio blue = key_to_fill_ratio(with_lights({named("key", 1.0), named("fill", 1.0, {0, 0, 1})}));
    EXPECT_NEAR(blue.ratio, 1.0 / 0.0722, 1e-12);
    // A point fill 2 away from the subject with inverse-square attenuation.
    Light fill = named("fill", 1.0);
    fill.type = LightType::point;
    fill.position = {0, 0, 2};
    fill.att_constant = 0.0, fill.att_quadratic = 1.0;
    EXPECT_NEAR(key_to_fill_ratio(with_lights({named("key", 1.0), fill})).ratio, 4.0, 1e-12);
    // A disabled fill gives no light: no ratio, and the reason.
    Light off = named("fill", 1.0);
    off.enabled = false;
    EXPECT_EQ(key_to_fill_ratio(with_lights({named("key", 1.0), off})).problem,
              "the fill light gives no light at the subject");
}

TEST(KeyToFillRatio, SaysWhichLightIsMissing) {
    EXPECT_EQ(key_to_fill_ratio(with_lights({named("fill", 1.0)})).problem, "no light named \"key\"");
    EXPECT_EQ(key_to_fill_ratio(with_lights({named("key", 1.0), named("back", 1.0)})).problem,
              "no light named \"fill\"");
}

TEST(KeyToFillRatio, OfAnAreaOrSkyLightIsNotComputedYetAndSaysSo) {
    Light key = named("key", 1.0), fill = named("fill", 0.5);
    key.type = LightType::rect;
    EXPECT_EQ(key_to_fill_ratio(with_lights({key, fill})).problem,
              "the key light is a rect light: its illuminance is not computed by this build yet");
    fill.type = LightType::sky;
    EXPECT_EQ(key_to_fill_ratio(with_lights({named("key", 1.0), fill})).problem,
              "the fill light is a sky light: its illuminance is not computed by this build yet");
    EXPECT_THROW(illuminance_at(fill, dvec3(0.0)), std::invalid_argument);
}

TEST(KeyToFillRatio, OfTheThreePointPresetsIsTwoAndAHalfToOne) {
    for (LightPreset preset : {LightPreset::three_point_white, LightPreset::three_point_warm}) {
        const KeyFillRatio r = key_to_fill_ratio(with_lights(light_preset(preset)));
        ASSERT_TRUE(r.ok());
        const double key_luminance = preset == LightPreset::three_point_white
                                         ? 1.0
                                         : 0.2126 * kWarmKey[0] + 0.7152 * kWarmKey[1] + 0.0722 * kWarmKey[2];
        EXPECT_NEAR(r.ratio, key_luminance / 0.4, 1e-12);
    }
}

TEST(KeyToFillRatio, SubjectIsTheCentroidOfTheObjectsWithoutFloors) {
    Scene scene = default_scene();
    scene.objects[0].center = {2, 0, 0};
    Object floor = scene.objects[0];
    floor.shape = Shape::plane;
    floor.center = {0, -5, 0};
    Object other = scene.objects[0];
    other.center = {0, 4, 0};
    scene.objects = {scene.objects[0], floor, other};
    EXPECT_EQ(subject_centre(scene), dvec3(1, 2, 0));
}

// ---- Light names in scene files ------------------------------------------------

json scene_with_light(const json& light) {
    return {{"camera", {{"projection", "perspective"}, {"position", {0, 0, 4}}, {"target", {0, 0, 0}},
                        {"fov_y_deg", 30}}},
            {"lights", json::array({light})},
            {"objects", json::array()}};
}

std::string error_of(const json& light) {
    try {
        scene_from_json(scene_with_light(light), "s.json", LoadContext::trusted());
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

TEST(LightNames, AreReadKeptOnSaveAndChecked) {
    const json light = {{"type", "directional"}, {"direction", {0, 0, 1}}, {"name", "Key light (warm) \u2600"}};
    const Scene scene = scene_from_json(scene_with_light(light), "s.json", LoadContext::trusted());
    EXPECT_EQ(scene.lights[0].name, "Key light (warm) \u2600");
    EXPECT_EQ(scene_from_json(scene_to_json(scene, PathWriting::absolute()), "again.json", LoadContext::trusted())
                  .lights[0]
                  .name,
              scene.lights[0].name);
    EXPECT_FALSE(scene_to_json(default_scene(), PathWriting::absolute())["lights"][0].contains("name"))
        << "absent stays absent";

    json bad = light;
    bad["name"] = 3;
    EXPECT_EQ(error_of(bad), "s.json: lights[0].name: must be a string");
    bad["name"] = "";
    EXPECT_EQ(error_of(bad), "s.json: lights[0].name: must be 1 to 64 bytes long");
    bad["name"] = std::string(65, 'k');
    EXPECT_EQ(error_of(bad), "s.json: lights[0].name: must be 1 to 64 bytes long");
    bad["name"] = "key\nfill";
    EXPECT_EQ(error_of(bad), "s.json: lights[0].name: must be UTF-8 text without control characters");
}

TEST(LightNames, ThreePointPresetsNameTheirLights) {
    const std::vector<Light> lights = light_preset(LightPreset::three_point_cool);
    ASSERT_EQ(lights.size(), 3u);
    EXPECT_EQ(lights[0].name, "key");
    EXPECT_EQ(lights[1].name, "fill");
    EXPECT_EQ(lights[2].name, "back");
    EXPECT_EQ(light_preset(LightPreset::paper_main_secondary)[1].name, "secondary");
}

}  // namespace
}  // namespace m3055
