// The paper's properties (docs/spec.md#4-paper-models), checked on the CPU reference: what w = 1,
// eq. 14, t_p = 0 and a single white light must give, that lights never
// depend on their order, that lights facing away contribute nothing, and that
// extreme parameters stay finite.
#include "models/model_table.h"
#include "reference/reference.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace m3055::ref {
namespace {

constexpr double kTight = 1e-12;

Light directional(dvec3 towards_light, double intensity = 1.0, dvec3 color = dvec3(1.0)) {
    Light light;
    light.type = LightType::directional;
    light.direction = glm::normalize(towards_light);
    light.intensity = intensity;
    light.color = color;
    return light;
}

SurfacePoint point_with(dvec3 N, dvec3 V) {
    SurfacePoint p;
    p.N = glm::normalize(N);
    p.P = p.N;  // on the unit sphere at the origin
    p.V = glm::normalize(V);
    return p;
}

Material highlight(dvec3 C0, double d, double w, double m) {
    Material mat = Material::of("highlight");
    mat.set_vec3("color", C0);
    mat.set_number("d", d);
    mat.set_number("w", w);
    mat.set_number("m", m);
    return mat;
}

// highlight(C0, 0.5, 1, 10) switched to the translucent model (keeps colour, d, w, m).
Material translucent(dvec3 C0, double t_n, double t_p) {
    Material mat = with_model(highlight(C0, 0.5, 1.0, 10.0), model_table().get("translucent"));
    mat.set_number("t_n", t_n);
    mat.set_number("t_p", t_p);
    return mat;
}

Material metal(const char* model, dvec3 C0, double d, std::vector<Lobe> lobes) {
    Material mat = Material::of(model);
    mat.set_vec3("color", C0);
    mat.set_number("d", d);
    mat.set_lobes(lobes);
    return mat;
}

// One material of every model, with sensible parameters.
std::vector<Material> every_model() {
    return {highlight({0.8, 0.2, 0.2}, 0.5, 0.9, 12.0),
            translucent({0.2, 0.5, 0.9}, 0.7, 1.0),
            metal("metal", {0.9, 0.6, 0.4}, 0.05, {{0.013, 0.2}, {0.1, 0.4}}),
            metal("metal_blinn", {0.7, 0.7, 0.8}, 0.05, {{0.5, 13.0}}),
            metal("metal_phong", {0.9, 0.8, 0.3}, 0.05, {{0.2, 20.0}, {0.8, 3.0}})};
}

// Translucent models are compared through their composite over a fixed C_B.
dvec3 shade_any(const Material& mat, const std::vector<Light>& lights, const SurfacePoint& p) {
    if (!is_translucent(mat)) return shade_opaque(mat, lights, p);
    const TranslucentShade s = shade_translucent(mat, lights, p);
    return s.color + s.transmittance * dvec3(0.3, 0.6, 0.1);
}

void expect_near(dvec3 actual, dvec3 expected, double tol, const char* what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(actual[c], expected[c], tol * std::max(1.0, std::fabs(expected[c])))
            << what << " channel " << c;
}

// A random unit vector in the hemisphere around `axis` with axis.v >= min_cos.
dvec3 random_direction(std::mt19937& rng, dvec3 axis, double min_cos) {
    std::normal_distribution<double> g(0.0, 1.0);
    for (;;) {
        const dvec3 v = glm::normalize(dvec3{g(rng), g(rng), g(rng)});
        if (glm::dot(v, axis) >= min_cos) return v;
    }
}

// ---- 4.1: w = 1 drives the highlight centre to display white --------------

TEST(HighlightModel, WOneGivesDisplayWhiteAtTheHighlightCentre) {
    for (dvec3 C0 : {dvec3(0.8, 0.2, 0.2), dvec3(0.0), dvec3(0.1, 0.9, 0.4), dvec3(1.0)})
        for (double d : {0.0, 0.5, 1.0})
            for (double m : {2.0, 10.0, 100.0}) {
                const Material mat = highlight(C0, d, 1.0, m);
                // N = V = L: R = V exactly, R.V = 1.
                const SurfacePoint p = point_with({0, 0, 1}, {0, 0, 1});
                const dvec3 C = shade_opaque(mat, {directional({0, 0, 1})}, p);
                EXPECT_EQ(C, dvec3(1.0)) << "d = " << d << " m = " << m;
                // A tilted mirror configuration: R.V = 1 up to rounding.
                const SurfacePoint q = point_with({0, 0, 1}, {-0.6, 0, 0.8});
                const dvec3 Cq = shade_opaque(mat, {directional({0.6, 0, 0.8})}, q);
                expect_near(Cq, dvec3(1.0), kTight, "tilted");
            }
}

// ---- 4.3: eq. 14 puts the main highlight centre at C0 -----------------------

TEST(MetalModel, EquationFourteenGivesC0AtTheMainHighlightCentre) {
    const SurfacePoint p = point_with({0, 0, 1}, {0, 0, 1});  // N = V = L: G = 1, NoH = 1
    const Light light = directional({0, 0, 1});
    // Fig. 10's lobes: 0.013 / 0.2^2 + 0.1 / 0.4^2 = 0.95 = 1 - d.
    for (dvec3 C0 : {dvec3(0.9, 0.6, 0.4), dvec3(0.3, 0.3, 0.9)}) {
        const Material fig10 = metal("metal", C0, 0.05, {{0.013, 0.2}, {0.1, 0.4}});
        expect_near(shade_opaque(fig10, {light}, p), C0, kTight, "Fig. 10 lobes");
    }
    // Any lobes rescaled to meet eq. 14.
    const double d = 0.1, m1 = 0.15, m2 = 0.5, share1 = 0.3;
    const double w1 = share1 * (1.0 - d) * m1 * m1, w2 = (1.0 - share1) * (1.0 - d) * m2 * m2;
    const Material rescaled = metal("metal", {0.5, 0.7, 0.2}, d, {{w1, m1}, {w2, m2}});
    expect_near(shade_opaque(rescaled, {light}, p), rescaled.vec3("color"), kTight, "rescaled");
}

// ---- 4.2: t_p = 0 is Newell's constant opacity -----------------------------

TEST(TranslucentModel, PowerZeroGivesConstantOpacityAtEveryAngle) {
    for (double t_n : {0.2, 0.5, 0.9})
        for (double NoV : {1.0, 0.7, 0.2, 0.0}) {
            const Material mat = translucent({0.2, 0.5, 0.9}, t_n, 0.0);
            const SurfacePoint p = point_with({0, 0, 1}, {std::sqrt(1.0 - NoV * NoV), 0, NoV});
            // No lights: no highlight, so the transmittance is exactly 1 - t.
            const TranslucentShade s = shade_translucent(mat, std::vector<Light>{}, p);
            expect_near(s.transmittance, dvec3(1.0 - t_n), kTight, "transmittance");
            expect_near(s.color, t_n * mat.number("d") * mat.vec3("color"), kTight, "colour");
        }
}

TEST(TranslucentModel, EdgeOnIsMoreOpaqueThanFacing) {
    const Material mat = translucent({0.2, 0.5, 0.9}, 0.8, 1.0);
    const double facing = shade_translucent(mat, std::vector<Light>{}, point_with({0, 0, 1}, {0, 0, 1})).transmittance.x;
    const double oblique = shade_translucent(mat, std::vector<Light>{}, point_with({0, 0, 1}, {0.8, 0, 0.6})).transmittance.x;
    const double edge_on = shade_translucent(mat, std::vector<Light>{}, point_with({0, 0, 1}, {1, 0, 0})).transmittance.x;
    EXPECT_NEAR(facing, 1.0, kTight);        // t = 0: clear
    EXPECT_NEAR(oblique, 1.0 - 0.8 * 0.4, kTight);
    EXPECT_NEAR(edge_on, 1.0 - 0.8, kTight);  // t = t_n
}

// ---- Lights commute ----------------------------------------------------------

TEST(AllModels, PermutingTheLightsChangesNothing) {
    Light key = directional({1, 1, 1}, 1.0, {1.0, 0.9, 0.7});
    Light fill = directional({-1, 0.2, 0.5}, 0.6, {0.6, 0.7, 1.0});
    fill.lobes = {{0.01, 0.4}};  // Beckmann override for `metal`
    Light lamp;
    lamp.type = LightType::point;
    lamp.position = {0.5, -2.0, 3.0};
    lamp.intensity = 2.0;
    lamp.color = {0.9, 1.0, 0.8};
    lamp.att_linear = 0.1;
    lamp.att_quadratic = 0.05;
    lamp.lobes = {{0.4, 8.0}};  // exponent override for metal_blinn / metal_phong
    lamp.lobe_kind = LobeKind::exponent;
    Light spot;
    spot.type = LightType::spot;
    spot.position = {-1.0, 2.0, 3.0};
    spot.spot_direction = glm::normalize(dvec3(1.0, -2.0, -3.0));
    spot.spot_exponent = 4.0;
    spot.color = {1.0, 0.5, 0.5};

    std::vector<Light> lights = {key, fill, lamp, spot};
    std::mt19937 rng(3055);
    for (const Material& mat : every_model()) {
        for (int sample = 0; sample < 40; ++sample) {
            const dvec3 V = random_direction(rng, {0, 0, 1}, 0.0);
            const SurfacePoint p = point_with(random_direction(rng, V, 0.05), V);
            std::vector<int> order = {0, 1, 2, 3};
            const dvec3 first = shade_any(mat, lights, p);
            while (std::next_permutation(order.begin(), order.end())) {
                std::vector<Light> permuted;
                for (int i : order) permuted.push_back(lights[i]);
                expect_near(shade_any(mat, permuted, p), first, kTight, mat.model_name().c_str());
            }
        }
    }
}

// ---- One white light, a = 1: the paper's own formulas -----------------------

TEST(AllModels, OneWhiteLightReproducesThePapersFormulas) {
    std::mt19937 rng(4);
    for (int sample = 0; sample < 200; ++sample) {
        const dvec3 V = random_direction(rng, {0, 0, 1}, 0.0);
        const dvec3 N = random_direction(rng, V, 0.05);
        const dvec3 L = random_direction(rng, N, 0.05);
        const SurfacePoint p = point_with(N, V);
        const std::vector<Light> lights = {directional(L)};

        const double cos_theta = glm::dot(N, L);
        const dvec3 R = 2.0 * cos_theta * N - L;
        const double cos_alpha = std::max(glm::dot(R, V), 0.0);  // highlight angle
        const dvec3 H = glm::normalize(L + V);
        const double NoH = glm::dot(N, H), NoV = glm::dot(N, V), VoH = glm::dot(V, H);

        // eq. 3-4: C = C1 + w cos^m a (1 - C1), C1 = [d + (1 - d) cos th] C0.
        const Material hl = highlight({0.8, 0.3, 0.1}, 0.5, 0.8, 15.0);
        const double d = hl.number("d"), w = hl.number("w"), m = hl.number("m");
        const dvec3 C1 = (d + (1.0 - d) * cos_theta) * hl.vec3("color");
        const dvec3 eq4 = C1 + w * std::pow(cos_alpha, m) * (dvec3(1.0) - C1);
        expect_near(shade_opaque(hl, lights, p), eq4, kTight, "eq. 4");

        // eq. 5-8: the same blend towards white over C1 = (1 - t) C_B + t C1.
        const Material tr = translucent({0.2, 0.5, 0.9}, 0.7, 1.3);
        const dvec3 C_B(0.3, 0.6, 0.1);
        const double t = tr.number("t_n") * std::pow(1.0 - NoV, tr.number("t_p"));
        const double td = tr.number("d");
        const dvec3 C1t = (1.0 - t) * C_B + t * (td + (1.0 - td) * cos_theta) * tr.vec3("color");
        const dvec3 eq8 = C1t + tr.number("w") * std::pow(cos_alpha, tr.number("m")) * (dvec3(1.0) - C1t);
        expect_near(shade_any(tr, lights, p), eq8, kTight, "eq. 5-8");

        // eq. 12-13: C = {d + sum_j w_j delta(m_j, a) G / (N.V)} C0, with the
        // textbook delta = exp(-tan^2 a / m^2) / (m^2 cos^4 a) and G as printed.
        const Material mt = metal("metal", {0.9, 0.6, 0.4}, 0.05, {{0.013, 0.2}, {0.1, 0.4}});
        const double alpha = std::acos(std::min(NoH, 1.0));
        const double G = std::min({1.0, 2.0 * NoH * NoV / VoH, 2.0 * NoH * cos_theta / VoH});
        double lobes = 0.0;
        for (const Lobe& lobe : mt.lobes())
            lobes += lobe.w * std::exp(-std::pow(std::tan(alpha), 2) / (lobe.m * lobe.m)) /
                     (lobe.m * lobe.m * std::pow(std::cos(alpha), 4));
        const dvec3 eq12 = (mt.number("d") + lobes * G / NoV) * mt.vec3("color");
        expect_near(shade_opaque(mt, lights, p), eq12, 1e-10, "eq. 12");  // acos/tan round-trip

        // eq. 15 and eq. 16.
        const Material bl = metal("metal_blinn", {0.7, 0.7, 0.8}, 0.05, {{0.6, 13.0}, {0.3, 2.0}});
        const dvec3 eq15 = (bl.number("d") + 0.6 * std::pow(NoH, 13.0) + 0.3 * std::pow(NoH, 2.0)) * bl.vec3("color");
        expect_near(shade_opaque(bl, lights, p), eq15, kTight, "eq. 15");
        const Material ph = metal("metal_phong", {0.9, 0.8, 0.3}, 0.05, {{0.2, 20.0}, {0.8, 3.0}});
        const dvec3 eq16 =
            (ph.number("d") + 0.2 * std::pow(cos_alpha, 20.0) + 0.8 * std::pow(cos_alpha, 3.0)) * ph.vec3("color");
        expect_near(shade_opaque(ph, lights, p), eq16, kTight, "eq. 16");
    }
}

// ---- Lights facing away contribute nothing -----------------------------------

// The shade with `light` must equal the shade with no light at all, for every
// model, even with m = 0 (where (R.V)^0 = 1 would otherwise add w).
void expect_no_contribution(const Light& light, const SurfacePoint& p, const char* what) {
    std::vector<Material> materials = every_model();
    materials.push_back(highlight({0.5, 0.5, 0.5}, 0.5, 1.0, 0.0));
    materials.push_back(metal("metal_phong", {0.5, 0.5, 0.5}, 0.05, {{1.0, 0.0}}));
    materials.push_back(metal("metal_blinn", {0.5, 0.5, 0.5}, 0.05, {{1.0, 0.0}}));
    for (const Material& mat : materials)
        EXPECT_EQ(shade_any(mat, {light}, p), shade_any(mat, {}, p)) << what << " " << mat.model_name();
}

TEST(AllModels, LightBehindTheSurfaceContributesNothing) {
    // R.V = 0.28 > 0 here although N.L = -0.6: only the N.L test stops it.
    expect_no_contribution(directional({0.8, 0, -0.6}), point_with({0, 0, 1}, {-0.8, 0, 0.6}), "below");
    expect_no_contribution(directional({0, 0, -1}), point_with({0, 0, 1}, {0, 0, 1}), "opposite");
}

TEST(AllModels, LightAtExactlyNinetyDegreesContributesNothing) {
    // N.L = 0 exactly, R.V = 0.6.
    expect_no_contribution(directional({1, 0, 0}), point_with({0, 0, 1}, {-0.6, 0, 0.8}), "grazing");
}

TEST(RenderReference, LightExactlyBehindTheObjectLeavesOnlyTheAmbientTerm) {
    for (const Material& mat : every_model()) {
        Scene lit;
        lit.display = {48, 32, 5, false};
        lit.objects.push_back({Shape::sphere, {0, 0, 0}, 1.0, mat});
        Light behind;
        behind.type = LightType::point;
        behind.position = {0.0, 0.0, -5.0};  // on the view axis, behind the sphere
        lit.lights = {behind, directional({0, 0, -1})};
        Scene dark = lit;
        dark.lights.clear();
        const ReferenceImage a = render_reference(lit), b = render_reference(dark);
        EXPECT_EQ(a.rgb, b.rgb) << mat.model_name();
        EXPECT_NE(a.coverage[16 * 48 + 24], 0u);  // the sphere is in view
    }
}

// The per-row callback (a progress display) is called once a row and changes nothing drawn.
TEST(RenderReference, TheRowCallbackCountsEveryRowAndChangesNoPixel) {
    Scene scene;
    scene.display = {48, 32, 5, false};
    scene.objects.push_back({Shape::sphere, {0, 0, 0}, 1.0, every_model().front()});
    scene.lights = {directional({1, 1, 1})};
    int rows = 0;
    const ReferenceImage counted = render_reference(scene, AreaQuadrature{}, nullptr, [&] { ++rows; });
    EXPECT_EQ(rows, 32);
    EXPECT_EQ(counted.rgb, render_reference(scene).rgb);
}

TEST(HighlightModel, ExponentZeroLightsEveryPointFacingTheLight) {
    // (R.V)^0 = 1 wherever N.L > 0, even where R.V <= 0.
    const Material mat = highlight({0.8, 0.2, 0.2}, 0.5, 0.5, 0.0);
    const dvec3 L = glm::normalize(dvec3(0.8, 0, 0.6));
    const SurfacePoint p = point_with({0, 0, 1}, {0.8, 0, 0.6});  // R.V = 0.28 - 0.64 < 0
    const dvec3 C1 = (0.5 + 0.5 * 0.6) * mat.vec3("color");
    expect_near(shade_opaque(mat, {directional(L)}, p), C1 + 0.5 * (dvec3(1.0) - C1), kTight, "m = 0");
}

// ---- Stability ---------------------------------------------------------------

TEST(AllModels, ExtremeParametersStayFinite) {
    std::vector<Material> extremes = {
        highlight({1, 1, 1}, 1.0, 1.0, 10000.0), highlight({0, 0, 0}, 0.0, 1.0, 0.0),
        translucent({1, 0, 0}, 1.0, 10.0), translucent({0, 1, 0}, 0.0, 0.0),
        metal("metal", {1, 1, 1}, 1.0, {{100.0, 0.001}, {100.0, 2.0}, {0.0, 0.001}, {1.0, 0.5}}),
        metal("metal_blinn", {1, 1, 1}, 1.0, {{100.0, 10000.0}, {100.0, 0.0}}),
        metal("metal_phong", {1, 1, 1}, 1.0, {{100.0, 10000.0}, {100.0, 0.0}})};
    Light strong = directional({0.3, 0.2, 1.0}, 10.0);
    Light near_lamp;
    near_lamp.type = LightType::spot;
    near_lamp.position = {0.0, 0.0, 1.0};  // exactly on the surface point (0, 0, 1)
    near_lamp.spot_exponent = 10000.0;
    near_lamp.att_constant = 0.0;
    const std::vector<Light> lights = {strong, near_lamp, directional({1, 0, 0}), directional({0, 0, 1})};

    std::vector<SurfacePoint> points = {point_with({0, 0, 1}, {0, 0, 1}), point_with({0, 0, 1}, {1, 0, 0}),
                                        point_with({0, 0, 1}, {1, 0, 1e-9}), point_with({0, 0, 1}, {1, 0, 1e-300})};
    std::mt19937 rng(1);
    for (int i = 0; i < 200; ++i) {
        const dvec3 V = random_direction(rng, {0, 0, 1}, 0.0);
        points.push_back(point_with(random_direction(rng, V, 0.0), V));
    }
    for (const Material& mat : extremes)
        for (const SurfacePoint& p : points) {
            const dvec3 C = shade_any(mat, lights, p);
            for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(C[c])) << mat.model_name();
        }
}

TEST(RenderReference, GrazingSilhouettesOfExtremeMaterialsStayFinite) {
    Scene scene;
    scene.display = {97, 61, 8, false};
    scene.lights = {directional({1, 1, 1}, 10.0), directional({0, 0, 1})};
    double x = -2.0;
    for (const Material& mat : {metal("metal", {1, 1, 1}, 0.0, {{100.0, 0.001}}),
                                highlight({1, 1, 1}, 0.5, 1.0, 10000.0), translucent({1, 1, 1}, 1.0, 10.0)}) {
        scene.objects.push_back({Shape::sphere, {x, 0.0, 0.0}, 0.9, mat});
        x += 2.0;
    }
    scene.camera.projection = Projection::orthographic;
    scene.camera.height = 2.5;
    const ReferenceImage image = render_reference(scene);
    for (double v : image.rgb) ASSERT_TRUE(std::isfinite(v));
}

// ---- Point and spot lights -----------------------------------------------------

TEST(Lights, PointLightAttenuationFollowsTheLectureFormula) {
    Light lamp;
    lamp.type = LightType::point;
    lamp.position = {0.0, 3.0, 4.0};
    lamp.intensity = 2.0;
    lamp.color = {1.0, 0.5, 0.25};
    const dvec3 P(0.0);  // r = 5

    LightSample s = sample_light(lamp, P);  // no attenuation fields: S_c = 1, S_l = S_q = 0
    expect_near(s.L, {0.0, 0.6, 0.8}, kTight, "L");
    expect_near(s.scale, 2.0 * lamp.color, kTight, "unattenuated");

    lamp.att_constant = 0.5;
    lamp.att_linear = 0.2;
    lamp.att_quadratic = 0.04;
    s = sample_light(lamp, P);
    expect_near(s.scale, 2.0 * lamp.color / (0.5 + 0.2 * 5.0 + 0.04 * 25.0), kTight, "attenuated");

    lamp.enabled = false;
    EXPECT_EQ(sample_light(lamp, P).scale, dvec3(0.0));
}

TEST(Lights, SpotFactorFollowsTheLectureFormula) {
    Light spot;
    spot.type = LightType::spot;
    spot.position = {0.0, 0.0, 5.0};
    spot.spot_direction = {0.0, 0.0, -1.0};
    spot.spot_exponent = 8.0;
    // On the axis: factor 1.
    expect_near(sample_light(spot, {0, 0, 0}).scale, dvec3(1.0), kTight, "axis");
    // Off the axis by angle g: cos^8 g.
    const dvec3 P(3.0, 0.0, 1.0);  // -L . dir = 4 / 5
    expect_near(sample_light(spot, P).scale, dvec3(std::pow(0.8, 8.0)), kTight, "off axis");
    // Behind the spot: nothing.
    EXPECT_EQ(sample_light(spot, {0, 0, 6}).scale, dvec3(0.0));
    // Exponent 0: an unrestricted point light.
    spot.spot_exponent = 0.0;
    expect_near(sample_light(spot, P).scale, dvec3(1.0), kTight, "exponent 0");
}

TEST(Lights, DirectionalLightScaleIsIntensityTimesColour) {
    Light light = directional({0, 1, 0}, 0.7, {1.0, 0.5, 0.0});
    light.lobes = {{0.01, 0.4}};
    const LightSample s = sample_light(light, {5, 5, 5});
    EXPECT_EQ(s.L, dvec3(0, 1, 0));
    expect_near(s.scale, {0.7, 0.35, 0.0}, kTight, "scale");
    // The light's own lobes are what a metal reads for it (lobes_for; no longer carried by the sample).
    const LobeList lobes = lobes_for(light, Material::of("metal"));
    ASSERT_EQ(lobes.size(), 1u);
    EXPECT_EQ(lobes[0].w, 0.01);
    EXPECT_EQ(lobes[0].m, 0.4);
}

TEST(MetalModel, PerLightLobesReplaceTheMaterialsForThatLight) {
    const SurfacePoint p = point_with({0, 0, 1}, {0, 0, 1});
    Light light = directional({0, 0, 1});
    light.lobes = {{0.01, 0.4}};  // Fig. 11's secondary light
    const Material mat = metal("metal", {0.9, 0.6, 0.4}, 0.05, {{0.013, 0.2}, {0.1, 0.4}});
    expect_near(shade_opaque(mat, {light}, p), (0.05 + 0.01 / 0.16) * mat.vec3("color"), kTight, "override");
    // Beckmann lobes do not apply to metal_blinn, which keeps its own.
    const Material blinn = metal("metal_blinn", {0.5, 0.5, 0.5}, 0.05, {{0.5, 13.0}});
    expect_near(shade_opaque(blinn, {light}, p), (0.05 + 0.5) * blinn.vec3("color"), kTight, "kind");
}

// ---- Compositing -----------------------------------------------------------------

TEST(RenderReference, CompositesTranslucentHitsBackToFrontOverTheOpaqueOne) {
    Scene scene;
    scene.display = {9, 9, 8, false};
    scene.background = {0.1, 0.2, 0.3};
    scene.lights = {directional({1, 1, 1}), directional({-1, 0.5, 0.3}, 0.5, {0.5, 0.5, 1.0})};
    // t_p = 0: constant opacity, so the order matters even where N.V = 1.
    const Material front = translucent({0.2, 0.5, 0.9}, 0.6, 0.0);
    const Material middle = translucent({0.9, 0.3, 0.1}, 0.8, 0.0);
    const Material back = highlight({0.9, 0.8, 0.2}, 0.5, 1.0, 20.0);
    // Listed out of depth order on purpose.
    scene.objects = {{Shape::sphere, {0, 0, -3.0}, 1.0, back},
                     {Shape::sphere, {0, 0, 1.0}, 0.5, front},
                     {Shape::sphere, {0, 0, -1.0}, 0.8, middle}};
    const ReferenceImage image = render_reference(scene);

    const Ray ray = camera_ray(scene.camera, 9, 9, 4, 4);
    auto shade_point = [&](const Object& o) {
        double t = 0.0;
        EXPECT_TRUE(intersect_sphere(ray, o.center, o.radius, &t));
        SurfacePoint p;
        p.P = ray.origin + t * ray.dir;
        p.N = glm::normalize(p.P - o.center);
        p.V = -ray.dir;
        return p;
    };
    const dvec3 C_back = shade_opaque(back, scene.lights, shade_point(scene.objects[0]));
    const TranslucentShade mid = shade_translucent(middle, scene.lights, shade_point(scene.objects[2]));
    const TranslucentShade fr = shade_translucent(front, scene.lights, shade_point(scene.objects[1]));
    const dvec3 expected = fr.color + fr.transmittance * (mid.color + mid.transmittance * C_back);
    const std::size_t i = 4 * 9 + 4;
    expect_near({image.rgb[3 * i], image.rgb[3 * i + 1], image.rgb[3 * i + 2]}, expected, kTight, "centre");
    EXPECT_TRUE(is_interior(image, 4, 4));
    EXPECT_EQ(image.coverage[0], 0u);  // the corner sees only the background
    expect_near({image.rgb[0], image.rgb[1], image.rgb[2]}, scene.background, 0.0, "corner");
}

TEST(RenderReference, OpaqueObjectHidesTranslucentOnesBehindIt) {
    Scene scene;
    scene.display = {9, 9, 8, false};
    scene.lights = {directional({1, 1, 1})};
    const Material solid = highlight({0.9, 0.8, 0.2}, 0.5, 1.0, 20.0);
    scene.objects = {{Shape::sphere, {0, 0, -2.0}, 1.0, translucent({0.2, 0.5, 0.9}, 0.6, 1.0)},
                     {Shape::sphere, {0, 0, 0.0}, 0.5, solid}};
    Scene alone = scene;
    alone.objects.erase(alone.objects.begin());
    const std::size_t i = 4 * 9 + 4;
    const ReferenceImage a = render_reference(scene), b = render_reference(alone);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(a.rgb[3 * i + c], b.rgb[3 * i + c]);
    EXPECT_NE(a.coverage[i], b.coverage[i]);  // but it is a different set of objects
}

}  // namespace
}  // namespace m3055::ref
