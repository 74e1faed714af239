// The polar plot's numbers (renderer/analysis/plane_curve.h): a
// light behind the surface gives no lobe (it used to be clamped to 90 deg and
// drew a full one), and a translucent object's curve at the view direction is
// the value the display shows at the matching pixel (it used to plot the
// opaque shading, which t_n and t_p do not change).
#include "analysis/plane_curve.h"
#include "image/image.h"
#include "models/model_table.h"
#include "scene/load.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>

namespace m3055 {
namespace {

Light white_light() {
    Light light;
    light.type = LightType::directional;
    light.direction = {0.0, 0.0, 1.0};
    return light;
}

TEST(PlaneCurve, ALightBehindTheSurfaceGivesNoLobe) {
    for (const ModelSpec& model : model_table().models()) {
        if (model.family == Family::translucent) continue;
        const Material material(model);
        for (double incidence : {90.5, 120.0, 142.0, 180.0}) {
            const PlaneCurve curve = plane_curve(material, white_light(), incidence, dvec3(0.3));
            EXPECT_TRUE(curve.light_behind) << model.name << " " << incidence;
            EXPECT_EQ(curve.max_value(), 0.0) << model.name << " " << incidence;
            EXPECT_NE(curve.quantity().find("behind"), std::string::npos);
        }
        // In front, the same light lights it (not a curve that is always 0).
        EXPECT_GT(plane_curve(material, white_light(), 30.0, dvec3(0.3)).max_value(), 0.0) << model.name;
        EXPECT_FALSE(plane_curve(material, white_light(), 89.0, dvec3(0.3)).light_behind);
    }
}

TEST(PlaneCurve, IncidenceIsNotClampedTo90Degrees) {
    Camera camera;
    camera.position = {0.0, 0.0, 5.0};
    camera.target = {0.0, 0.0, 0.0};
    Light light = white_light();
    light.direction = {std::sin(142.0 * 3.14159265358979323846 / 180.0), 0.0,
                       std::cos(142.0 * 3.14159265358979323846 / 180.0)};
    EXPECT_NEAR(incidence_at_target(light, camera), 142.0, 1e-9);
}

TEST(PlaneCurve, TheSkyIsPlottedFromItsZenith) {
    Camera camera;
    camera.position = {0.0, 0.0, 5.0};
    camera.target = {0.0, 0.0, 0.0};
    Light sky = white_light();
    sky.type = LightType::sky;
    sky.up = {0.0, 1.0, 0.0};
    EXPECT_NEAR(incidence_at_target(sky, camera), 90.0, 1e-9);
}

// A translucent sphere on a coloured background, rendered by `m3055 render`:
// the centre pixel (an odd-sized display, so its ray is the camera axis and
// N = V there) holds, unquantized (--raw), what the curve gives at view 0.
TEST(PlaneCurve, TranslucentCurveAtTheViewDirectionIsTheDisplayedValue) {
    test::TempDir dir;
    const nlohmann::json doc = {
        {"display", {{"width", 65}, {"height", 65}, {"bits", 8}}},
        {"background", {0.2, 0.45, 0.7}},
        {"camera", {{"projection", "perspective"}, {"position", {0, 0, 4.5}}, {"target", {0, 0, 0}},
                    {"up", {0, 1, 0}}, {"fov_y_deg", 30}}},
        {"lights", {{{"type", "directional"}, {"direction", {0.4, 0.5, 1.0}}, {"intensity", 0.9}}}},
        {"objects", {{{"shape", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1.0},
                      {"material", {{"model", "translucent"}, {"color", {0.8, 0.3, 0.2}}, {"d", 0.3}, {"w", 0.7},
                                    {"m", 20}, {"t_n", 0.35}, {"t_p", 2.5}}}}}}};
    test::write_text(dir.file("scene.json"), doc.dump());
    const test::RunResult run = test::run_m3055({"render", "--scene", dir.file("scene.json"), "--out",
                                                 dir.file("out.png"), "--raw", dir.file("out.pfm")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const RgbFloatImage pfm = read_pfm(dir.file("out.pfm"));
    ASSERT_EQ(pfm.width, 65);
    const Scene scene = load_scene_file(dir.file("scene.json"), LoadContext::trusted());
    const Material& material = scene.objects[0].material;
    const PlaneCurve curve =
        plane_curve(material, scene.lights[0], incidence_at_target(scene.lights[0], scene.camera), scene.background);
    ASSERT_TRUE(curve.translucent);
    const std::size_t centre = curve.values.size() / 2;
    ASSERT_EQ(curve.view_deg[centre], 0.0);
    for (int c = 0; c < 3; ++c) {
        const float shown = pfm.pixels[(std::size_t(32) * pfm.width + 32) * 3 + c];
        EXPECT_NEAR(curve.values[centre][c], shown, 1e-3) << "channel " << c;
    }
    // t_n changes the curve as it changes the display (the opaque shading would
    // not); off the axis, as t = t_n (1 - N.V)^t_p is 0 on it (spec 4.2).
    Material clearer = material;
    clearer.set_number("t_n", 0.05);
    const PlaneCurve other =
        plane_curve(clearer, scene.lights[0], incidence_at_target(scene.lights[0], scene.camera), scene.background);
    EXPECT_GT(glm::length(other.values[centre + 70] - curve.values[centre + 70]), 0.05);
}

TEST(PlaneCurve, RadialScales) {
    EXPECT_DOUBLE_EQ(radial_fraction(0.5, RadialScale::fixed, 1.0), 0.5);
    EXPECT_DOUBLE_EQ(radial_fraction(3.0, RadialScale::fixed, 1.0), 3.0);  // outside: drawn clipped
    EXPECT_DOUBLE_EQ(radial_fraction(1e-3, RadialScale::log, 1e3), 0.0);
    EXPECT_DOUBLE_EQ(radial_fraction(1.0, RadialScale::log, 1e3), 0.5);
    EXPECT_DOUBLE_EQ(radial_fraction(0.0, RadialScale::log, 1e3), 0.0);
    // model_max does not depend on where the light is, only on the material and the light's strength.
    const Material metal = Material::of("metal");
    Light a = white_light(), b = white_light();
    b.direction = {1.0, 0.2, 0.3};
    EXPECT_EQ(model_max(metal, a, dvec3(0.0)), model_max(metal, b, dvec3(0.0)));
}

// The default "lobe" scale puts the outer circle at the
// plotted curve's largest value rounded up to 1, 2 or 5 x 10^k: Fig. 10's
// metal lobe (about 5 at its 54.7 deg incidence, 40.6 over all incidences)
// reaches at least 40 % of the radius instead of running off "fixed, outer 1"
// or shrinking under "model max".
TEST(PlaneCurve, LobeScaleFitsThePlottedLobe) {
    EXPECT_EQ(nice_ceiling(0.7), 1.0);
    EXPECT_EQ(nice_ceiling(1.0), 1.0);
    EXPECT_EQ(nice_ceiling(1.3), 2.0);
    EXPECT_EQ(nice_ceiling(4.1), 5.0);
    EXPECT_EQ(nice_ceiling(6.0), 10.0);
    EXPECT_NEAR(nice_ceiling(0.031), 0.05, 1e-15);
    EXPECT_EQ(nice_ceiling(0.0), 1.0) << "a black curve";
    const Scene scene = load_scene_file(test::source_path("scenes/fig10.json"), LoadContext::trusted());
    const Light& light = scene.lights[0];
    const Material& metal = scene.objects[0].material;
    const PlaneCurve curve = plane_curve(metal, light, incidence_at_target(light, scene.camera), scene.background);
    const double top = lobe_top(curve);
    EXPECT_GT(curve.max_value(), 1.0) << "fixed, outer 1 would cut this lobe";
    EXPECT_GE(top, curve.max_value());
    EXPECT_GE(curve.max_value() / top, 0.4);
    EXPECT_LT(top, model_max(metal, light, scene.background)) << "model max flattens it";
    PlaneCurve brighter = curve;
    for (auto& v : brighter.values) v *= 3.0;
    EXPECT_GE(lobe_top(curve, &brighter), brighter.max_value()) << "B's curve counts too";
}

}  // namespace
}  // namespace m3055
