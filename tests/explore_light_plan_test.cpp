// The light plot's geometry (explore/light_plan.h): emitter outlines seen from
// above, and turning a light about the subject with its facing.
#include "explore/light_plan.h"

#include "scene/area_light.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>

namespace m3055::explore {
namespace {

Light rect_facing_origin() {
    Light light;
    light.type = LightType::rect;
    light.position = {0.0, 2.0, 4.0};
    light.normal = glm::normalize(-light.position);
    light.up = default_rect_up(light.normal);
    light.size[0] = 2.0;
    light.size[1] = 1.0;
    return light;
}

TEST(EmitterOutline, ARectsCornersSeenFromAbove) {
    const Light light = rect_facing_origin();
    const std::vector<PlanPoint> outline = emitter_outline(light);
    ASSERT_EQ(outline.size(), 4u);
    // Facing -z (tilted down): its width runs along x, its height foreshortened in z.
    double x_span = 0, z_span = 0;
    for (const PlanPoint& p : outline) x_span = std::max(x_span, std::abs(p.x)), z_span = std::max(z_span, std::abs(p.z));
    EXPECT_NEAR(x_span, 1.0, 1e-12);
    EXPECT_NEAR(z_span, 0.5 * std::sin(std::atan2(2.0, 4.0)), 1e-12);
}

TEST(EmitterOutline, ADiskFacingDownIsACircleAndPointLightsHaveNone) {
    Light disk;
    disk.type = LightType::disk;
    disk.normal = {0.0, -1.0, 0.0};
    disk.radius = 0.5;
    const std::vector<PlanPoint> rim = emitter_outline(disk, 16);
    ASSERT_EQ(rim.size(), 16u);
    for (const PlanPoint& p : rim) EXPECT_NEAR(std::hypot(p.x, p.z), 0.5, 1e-12);
    Light point;
    point.type = LightType::point;
    EXPECT_TRUE(emitter_outline(point).empty());
}

TEST(TurnToAzimuth, ARectTurnedAboutTheSubjectKeepsFacingIt) {
    Light light = rect_facing_origin();
    turn_to_azimuth(light, dvec3(0.0), 90.0);
    EXPECT_NEAR(light.position.x, 4.0, 1e-12);
    EXPECT_NEAR(light.position.y, 2.0, 1e-12);
    EXPECT_NEAR(light.position.z, 0.0, 1e-12);
    const dvec3 towards = glm::normalize(-light.position);
    EXPECT_NEAR(glm::dot(light.normal, towards), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(light.up, light.normal), glm::dot(default_rect_up(towards), towards), 1e-12);
}

TEST(TurnToAzimuth, APointLightMovesAndAnotherSubjectIsTheCentre) {
    Light light;
    light.type = LightType::point;
    light.position = {1.0, 3.0, 2.0};
    turn_to_azimuth(light, dvec3(1.0, 0.0, 0.0), 180.0);
    EXPECT_NEAR(light.position.x, 1.0, 1e-12);
    EXPECT_NEAR(light.position.y, 3.0, 1e-12);
    EXPECT_NEAR(light.position.z, -2.0, 1e-12);
}

// The plot's read-outs follow the document's revision, and only it.
TEST(LightPlanReadouts, FoundAgainOnlyWhenTheRevisionChanges) {
    Scene scene;
    Object sphere;
    sphere.center = {1.0, 0.5, -1.0};
    scene.objects.push_back(sphere);
    Light key = rect_facing_origin(), fill;
    key.name = "key";
    fill.name = "fill";
    fill.direction = {-1.0, 0.3, 1.0};
    fill.intensity = 0.25;
    scene.lights = {key, fill};

    LightPlanReadouts readouts;
    update_light_plan(readouts, scene, 7);
    EXPECT_EQ(readouts.subject, sphere.center);
    EXPECT_EQ(readouts.ratio.text(), key_to_fill_ratio(scene, sphere.center).text());

    scene.objects[0].center = {0.0, 0.0, 0.0};  // the same revision: kept
    update_light_plan(readouts, scene, 7);
    EXPECT_EQ(readouts.subject, sphere.center);
    update_light_plan(readouts, scene, 8);
    EXPECT_EQ(readouts.subject, dvec3(0.0));
    EXPECT_EQ(readouts.revision, 8u);
}

}  // namespace
}  // namespace m3055::explore
