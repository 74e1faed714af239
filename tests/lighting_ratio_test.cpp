// The key-to-fill ratio (renderer/analysis/lighting_ratio.h) and light names
// in scene files: what three-point lessons and grading rules are built on.
#include "analysis/lighting_ratio.h"
#include "scene/load.h"
#include "scene/area_light.h"
#include "scene/presets.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>

#include <cmath>
#include <utility>

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

TEST(KeyToFillRatio, IsTheKeysIrradianceOverTheFills) {
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
              "the fill light gives no light at the subject facing the camera");
}

TEST(KeyToFillRatio, SaysWhichLightIsMissing) {
    EXPECT_EQ(key_to_fill_ratio(with_lights({named("fill", 1.0)})).problem, "no light named \"key\"");
    EXPECT_EQ(key_to_fill_ratio(with_lights({named("key", 1.0), named("back", 1.0)})).problem,
              "no light named \"fill\"");
}

// ---- Each light type's irradiance, against an independent computation ---------

constexpr double kPi = 3.14159265358979323846;
const dvec3 kAt(0.0), kUp(0, 1, 0);

Light area(LightType type, dvec3 position, dvec3 normal, double intensity = 1.0) {
    Light light = named("", intensity);
    light.type = type;
    light.position = position;
    light.normal = glm::normalize(normal);
    light.up = std::fabs(light.normal.y) > 0.99 ? dvec3(0, 0, -1) : dvec3(0, 1, 0);
    return light;
}

// The integral over the emitter of (N.w)+ cos(theta_e) / r^2 dA by the midpoint
// rule on an n x n grid of (s, t) in [0, 1]^2: no horizon clipping, no closed
// form. `at(s, t)` gives the emitter's point and the area per unit (s, t).
template <class Point>
double brute_force(Point at, const dvec3& n_emitter, const dvec3& P, const dvec3& N, int n = 1000) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const auto [q, jacobian] = at((i + 0.5) / n, (j + 0.5) / n);
            const dvec3 d = q - P;
            const double r2 = glm::dot(d, d);
            const dvec3 w = d / std::sqrt(r2);
            sum += std::max(glm::dot(N, w), 0.0) * std::max(-glm::dot(w, n_emitter), 0.0) / r2 * jacobian;
        }
    return sum / (double(n) * n);
}

TEST(Irradiance, OfADirectionalLightIsItsLuminanceTimesTheCosineAndNothingFromBehind) {
    Light light = named("key", 0.8, {1.0, 0.5, 0.25});
    light.direction = glm::normalize(dvec3(1, 1, 1));
    const double Y = 0.2126 + 0.7152 * 0.5 + 0.0722 * 0.25;
    EXPECT_NEAR(irradiance_at(light, kAt, {0, 0, 1}), 0.8 * Y / std::sqrt(3.0), 1e-15);
    light.direction = {0, 0.6, -0.8};  // behind the subject: a rim light, no fill
    EXPECT_EQ(irradiance_at(light, kAt, {0, 0, 1}), 0.0);
    light.enabled = false;
    light.direction = {0, 0, 1};
    EXPECT_EQ(irradiance_at(light, kAt, {0, 0, 1}), 0.0);
}

TEST(Irradiance, OfASpotLightTakesItsConeAndDistance) {
    Light spot = named("key", 2.0);
    spot.type = LightType::spot;
    spot.position = {0, 3, 4};  // 5 away, 3/5 above the surface facing +z: cos = 4/5
    spot.spot_direction = glm::normalize(-spot.position + dvec3(0, 0.5, 0));
    spot.spot_exponent = 10;
    spot.att_constant = 0.0, spot.att_linear = 1.0;
    const double cone = std::pow(glm::dot(-glm::normalize(spot.position), spot.spot_direction), 10.0);
    EXPECT_NEAR(irradiance_at(spot, kAt, {0, 0, 1}), 2.0 * cone / 5.0 * 0.8, 1e-14);
}

TEST(Irradiance, OfARectOnItsAxisIsTheViewFactorOfItsFourCornerRectangles) {
    // The view factor from a point to a parallel a x b rectangle at height h with a
    // corner above it (Hottel): (X atan(Y/sqrt(1+X^2))/sqrt(1+X^2) + Y atan(X/sqrt(1+Y^2))/sqrt(1+Y^2)) / 2pi.
    const auto corner = [](double a, double b, double h) {
        const double X = a / h, Y = b / h, x = std::sqrt(1 + X * X), y = std::sqrt(1 + Y * Y);
        return (X / x * std::atan(Y / x) + Y / y * std::atan(X / y)) / (2 * kPi);
    };
    Light rect = area(LightType::rect, {0, 0, 1.5}, {0, 0, -1}, 3.0);
    rect.size[0] = 2.0, rect.size[1] = 1.0;
    // E = L pi F, L = a / A.
    EXPECT_NEAR(irradiance_at(rect, kAt, {0, 0, 1}), 3.0 / 2.0 * kPi * 4 * corner(1.0, 0.5, 1.5), 1e-14);
}

TEST(Irradiance, OfARectFarAwayIsAPointLightOfIntensityACosThetaE) {
    const dvec3 to_light = glm::normalize(dvec3(1, 2, 3));
    const double d = 200.0;
    Light rect = area(LightType::rect, d * to_light, {0.3, -1, -0.5}, 2.5);  // tilted: theta_e off its normal
    rect.size[0] = 0.4, rect.size[1] = 0.7;
    const double cos_e = glm::dot(-to_light, rect.normal);
    ASSERT_GT(cos_e, 0.2);
    Light point = named("", 2.5 * cos_e);
    point.type = LightType::point;
    point.position = rect.position;
    point.att_constant = 0.0, point.att_quadratic = 1.0;
    const dvec3 N = glm::normalize(dvec3(0.2, 0.1, 1));
    // The far field's own error is of the order of (size / d)^2 = 1.2e-5.
    EXPECT_NEAR(irradiance_at(rect, kAt, N) / irradiance_at(point, kAt, N), 1.0, 1e-5);
    // Behind it (its emitting side faces away) it gives nothing.
    rect.normal = -rect.normal;
    EXPECT_EQ(irradiance_at(rect, kAt, N), 0.0);
}

TEST(Irradiance, OfARectCutByTheHorizonIsTheBruteForceIntegral) {
    Light rect = area(LightType::rect, {0.4, 0.2, 0.6}, {-0.2, 0.1, -1}, 1.7);
    rect.size[0] = 1.2, rect.size[1] = 0.8;
    rect.color = {0.2, 0.9, 0.4};
    const RectFrame frame = rect_frame(rect);
    const dvec3 N = glm::normalize(dvec3(1, 0.1, 0.3));  // the rect straddles this point's horizon
    const auto at = [&](double s, double t) {
        return std::pair{rect.position + (s - 0.5) * rect.size[0] * frame.side0 + (t - 0.5) * rect.size[1] * frame.side1,
                         rect.size[0] * rect.size[1]};
    };
    const double Y = 0.2126 * 0.2 + 0.7152 * 0.9 + 0.0722 * 0.4;
    const double expected = 1.7 * Y / (1.2 * 0.8) * brute_force(at, rect.normal, kAt, N);
    ASSERT_GT(expected, 0.0);
    EXPECT_NEAR(irradiance_at(rect, kAt, N), expected, 1e-5 * expected);
}

TEST(Irradiance, OfADiskOnItsAxisIsPiRSquaredOverHSquaredPlusRSquared) {
    const double R = 0.7, h = 1.3;
    Light disk = area(LightType::disk, {0, 0, h}, {0, 0, -1}, 2.0);
    disk.radius = R;
    // E = L pi R^2 / (h^2 + R^2), L = a / (pi R^2).
    EXPECT_NEAR(irradiance_at(disk, kAt, {0, 0, 1}), 2.0 / (h * h + R * R), 1e-10);
}

TEST(Irradiance, OfADiskTiltedAndCutByTheHorizonIsTheBruteForceIntegral) {
    Light disk = area(LightType::disk, {0.2, 0.4, 1}, {0.1, -0.3, -1}, 1.0);
    disk.radius = 0.8;
    const dvec3 N = glm::normalize(dvec3(0.2, 1, 0.3));
    const dvec3 e0 = glm::normalize(glm::cross(disk.normal, dvec3(1, 0, 0))), e1 = glm::cross(disk.normal, e0);
    const auto at = [&](double s, double t) {  // polar: r = R s, phi = 2 pi t, dA = r R 2 pi ds dt
        const double r = disk.radius * s, phi = 2 * kPi * t;
        return std::pair{disk.position + r * (std::cos(phi) * e0 + std::sin(phi) * e1), r * disk.radius * 2 * kPi};
    };
    const double expected = 1.0 / (kPi * 0.64) * brute_force(at, disk.normal, kAt, N);
    ASSERT_GT(expected, 0.0);
    EXPECT_NEAR(irradiance_at(disk, kAt, N), expected, 1e-5 * expected);
    // Far away, a point light of intensity a cos(theta_e).
    const dvec3 to_light = glm::normalize(dvec3(-0.5, 0.5, 2));
    disk.position = 300.0 * to_light;
    disk.radius = 0.5;
    Light point = named("", glm::dot(-to_light, disk.normal));
    point.type = LightType::point;
    point.position = disk.position;
    point.att_constant = 0.0, point.att_quadratic = 1.0;
    EXPECT_NEAR(irradiance_at(disk, kAt, N) / irradiance_at(point, kAt, N), 1.0, 1e-5);  // (R / d)^2 = 2.8e-6
}

TEST(Irradiance, OfTheSkyIsTheLuneOfItsHemisphere) {
    Light sky = area(LightType::sky, {0, 0, 0}, {0, 0, 1}, 0.6);
    sky.up = kUp;
    // A unit sky lights an upward plane as a unit directional light from the zenith.
    EXPECT_NEAR(irradiance_at(sky, kAt, kUp), 0.6, 1e-15);
    EXPECT_NEAR(irradiance_at(sky, kAt, {0, 0, 1}), 0.3, 1e-15);  // a subject facing the camera sees half
    EXPECT_NEAR(irradiance_at(sky, kAt, -kUp), 0.0, 1e-15);
}

TEST(KeyToFillRatio, FacesTheCameraSoAFillBehindTheSubjectIsNoFill) {
    Scene scene = with_lights({named("key", 1.0), named("fill", 0.5)});
    scene.camera.position = {0, 0, 6};
    scene.lights[1].direction = glm::normalize(dvec3(-1, 0, -1));  // behind, to the left
    EXPECT_EQ(key_to_fill_ratio(scene).problem, "the fill light gives no light at the subject facing the camera");
    scene.lights[1].direction = glm::normalize(dvec3(-1, 0, 1));  // 45 degrees off the camera
    EXPECT_NEAR(key_to_fill_ratio(scene).ratio, 2.0 * std::sqrt(2.0), 1e-12);
    // From the subject, not the target: a subject right of the target faces the camera turned.
    scene.objects[0].center = {6, 0, 0};
    EXPECT_NEAR(key_to_fill_ratio(scene).ratio, std::sqrt(2.0), 1e-12);
}

TEST(KeyToFillRatio, OfARectKeyAndASkyFill) {
    Scene scene = with_lights({named("fill", 0.5), area(LightType::rect, {0, 0, 3}, {0, 0, -1}, 4.0)});
    scene.lights[0].type = LightType::sky;
    scene.lights[1].name = "key";
    scene.objects[0].center = dvec3(0.0);
    const KeyFillRatio r = key_to_fill_ratio(scene);
    ASSERT_TRUE(r.ok()) << r.problem;
    EXPECT_DOUBLE_EQ(r.fill_irradiance, 0.25);
    EXPECT_DOUBLE_EQ(r.key_irradiance, irradiance_at(scene.lights[1], dvec3(0.0), {0, 0, 1}));
    EXPECT_NEAR(r.ratio, r.key_irradiance / 0.25, 1e-15);
}

TEST(KeyToFillRatio, OfTheThreePointPresetsIsTheirLuminancesTimesTheirCosinesToTheCamera) {
    for (LightPreset preset : {LightPreset::three_point_white, LightPreset::three_point_warm}) {
        const std::vector<Light> lights = light_preset(preset);
        const KeyFillRatio r = key_to_fill_ratio(with_lights(lights));
        ASSERT_TRUE(r.ok());
        const double key_luminance = preset == LightPreset::three_point_white
                                         ? 1.0
                                         : 0.2126 * kWarmKey[0] + 0.7152 * kWarmKey[1] + 0.0722 * kWarmKey[2];
        // The default camera looks along -z at the subject: the cosine is a direction's z.
        const Light &key = lights[std::size_t(r.key)], &fill = lights[std::size_t(r.fill)];
        EXPECT_NEAR(r.ratio, key_luminance * key.direction.z / (0.4 * fill.direction.z), 1e-12);
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
