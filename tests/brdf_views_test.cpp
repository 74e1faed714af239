// BRDF Explorer's views as numbers (analysis/brdf_views.h), shared by `m3055
// plot` and the explorer's "BRDF views" window: for the project's
// lambert.brdf (f = kd / pi) every view has a value known in closed form, and
// the explorer's cache computes a view again only when its inputs change.
#include "analysis/brdf_views.h"
#include "brdf_file/brdf_model.h"
#include "gl/context.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace m3055 {
namespace {

Material lambert_file(const dvec3& kd) {
    const BrdfModel& model = load_brdf_model(test::source_path("tests/data/brdf/lambert.brdf"));
    Material m(*model.spec);
    m.set_vec3(model.field("kd"), kd);
    return m;
}

TEST(BrdfViews, LambertSliceAlbedoAndLobeAreKnownInClosedForm) {
    const auto context = HeadlessContext::create(Backend::automatic);
    BrdfGrid grid(context->gl());
    const Material m = lambert_file({0.6, 0.3, 0.1});
    const ThetaSlice slice = theta_slice(grid, m, 30);
    ASSERT_EQ(slice.f.size(), 900u);
    int above = 0;
    for (std::size_t k = 0; k < slice.f.size(); ++k)
        if (!slice.below[k]) {
            EXPECT_NEAR(slice.f[k], 0.6 / M_PI, 1e-5);
            ++above;
        }
    EXPECT_EQ(above, 900) << "phi_d = 90 deg: N.L = N.V = cos theta_d cos theta_h > 0 everywhere";

    const AlbedoCurve albedo = albedo_curve(grid, m, 16, 32);
    EXPECT_EQ(albedo.samples, 512u);
    ASSERT_EQ(albedo.albedo.size(), 90u);
    for (double a : albedo.albedo) EXPECT_NEAR(a, 0.6, 2e-3);  // the midpoint rule's error

    const Lobe3d lobe = lobe_3d(grid, m, 60.0);
    EXPECT_NEAR(lobe.top, 0.6 / M_PI * 0.5, 1e-5);
    for (double v : lobe.value) EXPECT_NEAR(v, lobe.top, 1e-5) << "f (N.L) does not depend on V";
}

TEST(BrdfViews, TheCacheComputesAViewAgainOnlyWhenItsInputsChange) {
    const auto context = HeadlessContext::create(Backend::automatic);
    BrdfViews views(context->gl());
    const Material a = lambert_file({0.6, 0.3, 0.1}), b = lambert_file({0.2, 0.3, 0.1});
    views.slice(a);
    views.slice(a);
    views.albedo(a);
    views.lobe(a, 30.0);
    views.lobe(a, 30.0);
    EXPECT_EQ(views.evaluations(), 3);
    views.lobe(a, 31.0);
    EXPECT_EQ(views.evaluations(), 4);
    EXPECT_NEAR(views.slice(b).max_value(), 0.3 / M_PI, 1e-5);
    EXPECT_EQ(views.evaluations(), 5);
}

}  // namespace
}  // namespace m3055
