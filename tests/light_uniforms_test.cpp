// The lights as the shaders get them (passes/light_uniforms.h): an area light's
// frame and size, the shadow flags, and the work a light costs.
#include "passes/light_uniforms.h"

#include <gtest/gtest.h>

#include <cmath>

namespace m3055 {
namespace {

Light of_type(LightType type) {
    Light light;
    light.type = type;
    return light;
}

double length3(const float* v) { return std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]); }

TEST(LightUniforms, PlainLightsNeedNeitherAreaSamplingNorShadows) {
    const LightUniforms u = pack_lights({of_type(LightType::directional), of_type(LightType::spot)});
    EXPECT_EQ(u.count, 2);
    EXPECT_FALSE(u.any_area);
    EXPECT_FALSE(u.any_shadow);
    EXPECT_EQ(u.work, 2u);
}

TEST(LightUniforms, ARectCarriesItsHalfSidesAlongItsFrame) {
    Light rect = of_type(LightType::rect);
    rect.position = dvec3(1.0, 3.0, 0.0);
    rect.normal = dvec3(0.0, -1.0, 0.0);
    rect.up = dvec3(0.0, 0.0, -1.0);
    rect.size[0] = 2.0;
    rect.size[1] = 0.5;
    const LightUniforms u = pack_lights({rect});
    ASSERT_EQ(u.count, 1);
    EXPECT_TRUE(u.any_area);
    EXPECT_FLOAT_EQ(u.vector[3], float(shader_type(LightType::rect)));
    EXPECT_FLOAT_EQ(u.vector[1], 3.0f);
    EXPECT_NEAR(length3(&u.extent[0]), 1.0, 1e-6);   // size[0] / 2, along N x U
    EXPECT_NEAR(length3(&u.extent[4]), 0.25, 1e-6);  // size[1] / 2, along U
    EXPECT_NEAR(u.extent[6], -0.25, 1e-6);  // along U
    // The scale is the radiance a c / area.
    EXPECT_NEAR(u.scale[0], 1.0 / (2.0 * 0.5), 1e-6);
}

TEST(LightUniforms, ADisksAxesAreItsRadiusAcrossItsNormal) {
    Light disk = of_type(LightType::disk);
    disk.normal = dvec3(0.0, 0.0, 1.0);
    disk.radius = 0.5;
    const LightUniforms u = pack_lights({disk});
    EXPECT_NEAR(length3(&u.extent[0]), 0.5, 1e-6);
    EXPECT_NEAR(length3(&u.extent[4]), 0.5, 1e-6);
    EXPECT_NEAR(u.extent[2], 0.0, 1e-6);  // both axes in the disk's plane
    EXPECT_NEAR(u.extent[6], 0.0, 1e-6);
}

TEST(LightUniforms, ShadowFlagsAndTheWorkTheyCost) {
    Light sky = of_type(LightType::sky);
    sky.shadow = true;
    Light point = of_type(LightType::point);
    point.shadow = true;
    const LightUniforms render = pack_lights({point, sky}, dvec3(0.0), kRenderSampling);
    EXPECT_EQ(render.shadow, (std::vector<int>{1, 1}));
    EXPECT_TRUE(render.any_shadow);
    const LightUniforms fast = pack_lights({point, sky}, dvec3(0.0), kFastSampling);
    EXPECT_GT(render.work, fast.work);
    EXPECT_EQ(fast.work, (1u + 10u) + (2u + 10u));  // one ray to the point light, one to the sky's centre sample
}

TEST(LightUniforms, DisabledLightsReachNoShaderWhateverTheirType) {
    Light rect = of_type(LightType::rect);
    rect.enabled = false;
    Light dark = of_type(LightType::sky);
    dark.intensity = 0.0;
    const LightUniforms u = pack_lights({rect, dark});
    EXPECT_EQ(u.count, 0);
    EXPECT_FALSE(u.any_area);
}

}  // namespace
}  // namespace m3055
