// A light's colour as the explorer's Lights panel changes it (scene/light_colour.h):
// RGB, a black body or a CIE illuminant, and the studio preset built on them.
// An edited light must be the light the loader makes of the same JSON, so the
// explorer's display and `m3055 render` of the saved scene agree.
#include "scene/light_colour.h"
#include "scene/load.h"
#include "scene/presets.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace m3055 {
namespace {

// The light the loader makes of `light`'s JSON (a one-light scene, saved and read back).
Light reloaded(const Light& light) {
    Scene scene = default_scene();
    scene.lights = {light};
    return scene_from_json(scene_to_json(scene, PathWriting::absolute()), "light.json", LoadContext::trusted())
        .lights.at(0);
}

TEST(LightColour, ATemperatureGivesTheLoadersColourAndReplacesTheRgb) {
    Light light;
    light.color = {0.2, 0.4, 0.6};
    std::string error;
    ASSERT_TRUE(set_temperature(light, 3200.0, &error)) << error;
    EXPECT_EQ(colour_source(light), LightColourSource::temperature);
    EXPECT_EQ(light.temperature_k, 3200.0);
    EXPECT_GT(light.color.r, light.color.b) << "3200 K is warm";
    const Light loaded = reloaded(light);
    EXPECT_EQ(loaded.temperature_k, 3200.0);
    EXPECT_EQ(loaded.color, light.color) << "the same RGB as the saved scene loads to";
}

TEST(LightColour, TemperaturesOutsideTheFormatsRangeAreClamped) {
    Light light;
    ASSERT_TRUE(set_temperature(light, 10.0, nullptr));
    EXPECT_EQ(light.temperature_k, kMinLightKelvin);
    ASSERT_TRUE(set_temperature(light, 1e6, nullptr));
    EXPECT_EQ(light.temperature_k, kMaxLightKelvin);
}

TEST(LightColour, AnIlluminantReplacesATemperatureAndLoadsBackTheSame) {
    Light light;
    ASSERT_TRUE(set_temperature(light, 2000.0, nullptr));
    std::string error;
    ASSERT_TRUE(set_illuminant(light, "A", &error)) << error;
    EXPECT_EQ(colour_source(light), LightColourSource::illuminant);
    EXPECT_EQ(light.temperature_k, 0.0);
    const Light loaded = reloaded(light);
    EXPECT_EQ(loaded.illuminant, "A");
    EXPECT_EQ(loaded.color, light.color);
}

TEST(LightColour, AnUnknownIlluminantIsRefusedAndTheLightKept) {
    Light light;
    ASSERT_TRUE(set_illuminant(light, "D65", nullptr));
    const Light before = light;
    std::string error;
    EXPECT_FALSE(set_illuminant(light, "D64", &error));
    EXPECT_NE(error.find("D64"), std::string::npos) << error;
    EXPECT_EQ(light.illuminant, before.illuminant);
    EXPECT_EQ(light.color, before.color);
}

TEST(LightColour, RgbClearsTheSpectrumAndIsClampedToTheFormatsRange) {
    Light light;
    ASSERT_TRUE(set_illuminant(light, "D65", nullptr));
    set_rgb_colour(light, {1.5, 0.5, -0.25});
    EXPECT_EQ(colour_source(light), LightColourSource::rgb);
    EXPECT_TRUE(light.illuminant.empty());
    EXPECT_EQ(light.color, dvec3(1.0, 0.5, 0.0));
    EXPECT_EQ(reloaded(light).color, light.color);
}

TEST(LightColour, EveryIlluminantNameIsAccepted) {
    ASSERT_FALSE(light_illuminant_names().empty());
    for (const std::string& name : light_illuminant_names()) {
        Light light;
        std::string error;
        EXPECT_TRUE(set_illuminant(light, name, &error)) << name << ": " << error;
    }
}

TEST(LightPresets, StudioIsATungstenKeyAndDaylightFillAndBack) {
    const std::vector<Light> lights = light_preset(LightPreset::three_point_studio);
    ASSERT_EQ(lights.size(), 3u);
    EXPECT_EQ(lights[0].name, "key");
    EXPECT_EQ(lights[0].temperature_k, 3200.0);
    EXPECT_EQ(lights[1].temperature_k, 5600.0);
    EXPECT_EQ(lights[2].temperature_k, 5600.0);
    // The same directions and intensities as the RGB three-point presets.
    const std::vector<Light> white = light_preset(LightPreset::three_point_white);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(lights[i].direction, white[i].direction);
        EXPECT_EQ(lights[i].intensity, white[i].intensity);
    }
    const double key_warmth = lights[0].color.r / lights[0].color.b, fill_warmth = lights[1].color.r / lights[1].color.b;
    EXPECT_GT(key_warmth, fill_warmth) << "the key is warmer than the fill";
}

}  // namespace
}  // namespace m3055
