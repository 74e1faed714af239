// The explorer's polar plot of a .brdf model (analysis/plane_curve_gpu.h): the
// project's own lambert.brdf and blinn_phong.brdf, evaluated on the GPU, give
// the curve the CPU reference gives for the built-in lambert and blinn_phong,
// and the cache evaluates again only when an input changes.
#include "analysis/plane_curve_gpu.h"
#include "brdf_file/brdf_model.h"
#include "gl/context.h"
#include "frame/renderer.h"
#include "scene/presets.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace m3055 {
namespace {

Material file_material(const std::string& file, const std::vector<std::pair<std::string, dvec3>>& colours,
                       const std::vector<std::pair<std::string, double>>& numbers) {
    const BrdfModel& model = load_brdf_model(test::source_path("tests/data/brdf/" + file));
    Material m(*model.spec);
    for (const auto& [name, value] : colours) m.set_vec3(model.field(name), value);
    for (const auto& [name, value] : numbers) m.set_number(model.field(name), value);
    return m;
}

Light coloured_light() {
    Light light;
    light.intensity = 0.8;
    light.color = {1.0, 0.9, 0.7};
    return light;
}

// Every view direction, every channel: |gpu - cpu| <= 1e-3 max(1, |cpu|).
void expect_same_curve(const PlaneCurve& gpu, const PlaneCurve& cpu, const std::string& what) {
    ASSERT_EQ(gpu.values.size(), cpu.values.size()) << what;
    double worst = 0.0;
    for (std::size_t k = 0; k < cpu.values.size(); ++k) {
        EXPECT_EQ(gpu.view_deg[k], cpu.view_deg[k]);
        for (int c = 0; c < 3; ++c) {
            const double ref = cpu.values[k][c];
            worst = std::max(worst, std::abs(gpu.values[k][c] - ref) / std::max(1.0, std::abs(ref)));
        }
    }
    EXPECT_LE(worst, 1e-3) << what;
    EXPECT_EQ(gpu.light_behind, cpu.light_behind) << what;
}

TEST(PlaneCurveGpu, LambertFileIsTheBuiltInLambertCurve) {
    const auto context = HeadlessContext::create(Backend::automatic);
    PlaneCurves curves(context->gl());
    Material builtin = Material::of("lambert");
    builtin.set_vec3("kd", {0.7, 0.3, 0.2});
    const Material file = file_material("lambert.brdf", {{"kd", {0.7, 0.3, 0.2}}}, {});
    for (double incidence : {0.0, 30.0, 75.0, 120.0}) {
        const PlaneCurve cpu = plane_curve(builtin, coloured_light(), incidence, dvec3(0.0));
        const PlaneCurve gpu = curves.curve(file, coloured_light(), incidence, dvec3(0.0));
        expect_same_curve(gpu, cpu, "lambert at " + std::to_string(incidence));
        if (incidence < 90.0) {
            EXPECT_GT(gpu.max_value(), 0.1);
        }
    }
}

TEST(PlaneCurveGpu, BlinnPhongFileIsTheBuiltInBlinnPhongCurve) {
    const auto context = HeadlessContext::create(Backend::automatic);
    PlaneCurves curves(context->gl());
    for (double n : {1.0, 32.0, 200.0}) {
        Material builtin = Material::of("blinn_phong");
        builtin.set_vec3("kd", {0.7, 0.3, 0.2});
        builtin.set_vec3("ks", {0.9, 0.9, 0.8});
        builtin.set_number("shininess", n);
        const Material file =
            file_material("blinn_phong.brdf", {{"kd", {0.7, 0.3, 0.2}}, {"ks", {0.9, 0.9, 0.8}}}, {{"shininess", n}});
        for (double incidence : {10.0, 45.0, 80.0}) {
            const PlaneCurve cpu = plane_curve(builtin, coloured_light(), incidence, dvec3(0.0));
            expect_same_curve(curves.curve(file, coloured_light(), incidence, dvec3(0.0)), cpu,
                              "blinn_phong n " + std::to_string(n) + " at " + std::to_string(incidence));
        }
        EXPECT_NEAR(curves.model_max(file, coloured_light(), dvec3(0.0)),
                    model_max(builtin, coloured_light(), dvec3(0.0)), 1e-3 * std::max(1.0, model_max(builtin, coloured_light(), dvec3(0.0))));
    }
}

TEST(PlaneCurveGpu, EvaluatesAgainOnlyWhenAnInputChanges) {
    const auto context = HeadlessContext::create(Backend::automatic);
    PlaneCurves curves(context->gl());
    Material file = file_material("lambert.brdf", {}, {});
    curves.curve(file, coloured_light(), 30.0, dvec3(0.0));
    curves.curve(file, coloured_light(), 30.0, dvec3(0.0));
    EXPECT_EQ(curves.gpu_evaluations(), 1);
    curves.curve(file, coloured_light(), 31.0, dvec3(0.0));
    EXPECT_EQ(curves.gpu_evaluations(), 2);
    file = file_material("lambert.brdf", {{"kd", {0.1, 0.2, 0.3}}}, {});
    const PlaneCurve changed = curves.curve(file, coloured_light(), 31.0, dvec3(0.0));
    EXPECT_EQ(curves.gpu_evaluations(), 3);
    EXPECT_NEAR(changed.values[90].b, 0.3 * 0.8 * 0.7 * std::cos(31.0 * M_PI / 180.0), 1e-5);
    // A built-in model goes to the CPU reference: no GPU work.
    curves.curve(Material::of("lambert"), coloured_light(), 31.0, dvec3(0.0));
    EXPECT_EQ(curves.gpu_evaluations(), 3);
}

// The explorer's context: the renderer has drawn (its general warm-up
// includes translucent objects, which leave a dual-source blend function set)
// before the plot asks the grid; the grid must not inherit that state.
TEST(PlaneCurveGpu, WorksAfterTheRendererDrewTranslucentObjects) {
    const auto context = HeadlessContext::create(Backend::automatic);
    Renderer renderer(context->gl());
    renderer.warm_up_general_programs();
    PlaneCurves curves(context->gl());
    const PlaneCurve curve = curves.curve(file_material("lambert.brdf", {}, {}), coloured_light(), 30.0, dvec3(0.0));
    EXPECT_NEAR(curve.values[90].r, 0.7 * 0.8 * std::cos(30.0 * M_PI / 180.0), 1e-5);
}

}  // namespace
}  // namespace m3055
