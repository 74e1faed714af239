// The lights as the shaders get them (passes/light_uniforms.h): which lights the
// GPU path does not draw yet, named by their place in the scene.
#include "passes/light_uniforms.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace m3055 {
namespace {

Light of_type(LightType type) {
    Light light;
    light.type = type;
    return light;
}

TEST(LightUniforms, AreaAndSkyLightsAndShadowsAreNamedAsNotDrawnYet) {
    EXPECT_EQ(undrawn_light({of_type(LightType::directional), of_type(LightType::point), of_type(LightType::spot)}),
              std::nullopt);
    EXPECT_EQ(undrawn_light({of_type(LightType::point), of_type(LightType::rect)}),
              "lights[1].type: rect lights are not drawn by this build yet");
    EXPECT_EQ(undrawn_light({of_type(LightType::disk)}), "lights[0].type: disk lights are not drawn by this build yet");
    Light sky = of_type(LightType::sky);
    sky.enabled = false;  // refused all the same: the next engineer draws it, or it stays refused
    EXPECT_EQ(undrawn_light({sky}), "lights[0].type: sky lights are not drawn by this build yet");
    Light shadowed = of_type(LightType::spot);
    shadowed.shadow = true;
    EXPECT_EQ(undrawn_light({of_type(LightType::directional), shadowed}),
              "lights[1].shadow: shadows are not drawn by this build yet");
}

TEST(LightUniforms, PackingRefusesWhatItCannotDraw) {
    EXPECT_EQ(pack_lights({of_type(LightType::point)}).count, 1);
    EXPECT_THROW(pack_lights({of_type(LightType::rect)}), std::logic_error);
}

}  // namespace
}  // namespace m3055
