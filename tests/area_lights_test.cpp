// Area and sky lights and shadows in the CPU reference (reference/lit_point.h,
// docs/spec.md#75-area-lights-the-sky-and-shadows): the closed forms (Lambert's
// polygon formula, a disk on its axis, the sky's identity) and the quadrature
// held to each other, the far field, the limit of many small lights, every
// model under every new light, and shadows against exact geometry.
#include "reference/emitters.h"
#include "reference/lit_point.h"
#include "reference/reference.h"
#include "reference/scene_bvh.h"

#include "models/model_table.h"
#include "numeric/angles.h"
#include "scene/area_light.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace m3055::ref {
namespace {

using numeric::kPi;

Light rect(dvec3 position, dvec3 normal, double w, double h, double intensity = 1.0) {
    Light light;
    light.type = LightType::rect;
    light.position = position;
    light.normal = glm::normalize(normal);
    light.up = default_rect_up(light.normal);
    light.size[0] = w;
    light.size[1] = h;
    light.intensity = intensity;
    return light;
}

Light disk(dvec3 position, dvec3 normal, double radius, double intensity = 1.0) {
    Light light;
    light.type = LightType::disk;
    light.position = position;
    light.normal = glm::normalize(normal);
    light.radius = radius;
    light.intensity = intensity;
    return light;
}

Light sky(double intensity = 1.0) {
    Light light;
    light.type = LightType::sky;
    light.intensity = intensity;
    return light;
}

Light directional(dvec3 towards) {
    Light light;
    light.direction = glm::normalize(towards);
    return light;
}

Light point_light(dvec3 position, double intensity = 1.0) {
    Light light;
    light.type = LightType::point;
    light.position = position;
    light.intensity = intensity;
    light.att_constant = 0.0;
    light.att_quadratic = 1.0;  // 1 / r^2
    return light;
}

Material lambert(double kd = 1.0) {
    Material material = Material::of("lambert");
    material.set_vec3("kd", dvec3(kd));
    return material;
}

SurfacePoint at(dvec3 P, dvec3 N, dvec3 V = {0, 0, 0}) {
    const dvec3 n = glm::normalize(N);
    return {P, n, V == dvec3(0.0) ? n : glm::normalize(V)};
}

LightingOptions quadrature_only() {
    LightingOptions options;
    options.quadrature.closed_forms = false;
    return options;
}

double relative(double got, double want) { return std::fabs(got - want) / std::max(1.0, std::fabs(want)); }

// ---- closed forms and the quadrature ------------------------------------------------

TEST(AreaLights, LambertUnderARectIsLambertsFormulaAndTheQuadratureAgrees) {
    const Light light = rect({0.3, 2, 0.1}, {0.1, -1, 0.2}, 1.5, 0.7, 2.0);
    const Material material = lambert(0.8);
    // Facing it, tilted, and so tilted that the horizon cuts the rect.
    for (const dvec3& N : {dvec3(0, 1, 0), dvec3(0.5, 1, 0), dvec3(1, 0.3, 0), dvec3(-1, 0.05, 0.2)}) {
        const SurfacePoint p = at({0, 0, 0}, N);
        const double closed = shade_opaque(material, {light}, p).r;
        EXPECT_DOUBLE_EQ(closed, 0.8 * radiance(light).r * *projected_solid_angle(light, p));
        AreaStats stats;
        LightingOptions options = quadrature_only();
        options.stats = &stats;
        const double quadrature = shade_opaque(material, {light}, p, dvec3(0.0), options).r;
        EXPECT_LE(relative(quadrature, closed), 1e-5) << N.x << " " << N.y << " " << N.z;
        EXPECT_EQ(stats.integrals, 1);
        EXPECT_EQ(stats.unconverged, 0);
        EXPECT_GT(closed, 0.0);
    }
}

TEST(AreaLights, ADiskOnItsAxisGivesAOverHSquaredPlusRSquared) {
    // A Lambertian disk of intensity a, radiance a / (pi R^2): a facing white Lambert point gets a / (h^2 + R^2).
    for (const double R : {0.05, 0.5, 2.0}) {
        const double h = 1.5, a = 3.0;
        const Light light = disk({1, 2, 3 + h}, {0, 0, -1}, R, a);
        const double got = shade_opaque(lambert(), {light}, at({1, 2, 3}, {0, 0, 1})).r;
        EXPECT_LE(relative(got, a / (h * h + R * R)), 1e-5) << R;
    }
}

TEST(AreaLights, AUnitSkyLightsAnUpwardWhitePlaneAsAUnitLightFromTheZenith) {
    const SurfacePoint up = at({0, 0, 0}, {0, 1, 0});
    const double zenith = shade_opaque(lambert(), {directional({0, 1, 0})}, up).r;
    EXPECT_EQ(zenith, 1.0);
    EXPECT_DOUBLE_EQ(shade_opaque(lambert(), {sky()}, up).r, zenith);
    EXPECT_LE(relative(shade_opaque(lambert(), {sky()}, up, dvec3(0.0), quadrature_only()).r, zenith), 1e-5);
    // Tilted by t, a plane sees the lune: (1 + cos t) / 2 of it.
    for (const double t : {0.4, 1.3, 2.5}) {
        const SurfacePoint p = at({0, 0, 0}, {std::sin(t), std::cos(t), 0});
        EXPECT_LE(relative(shade_opaque(lambert(), {sky()}, p, dvec3(0.0), quadrature_only()).r, 0.5 * (1 + std::cos(t))),
                  1e-5)
            << t;
    }
}

TEST(AreaLights, FarAwayARectIsAPointLightOfIntensityACosThetaEWithInverseSquareFalloff) {
    const Material phong = [] {
        Material m = Material::of("phong");
        m.set_vec3("kd", dvec3(0.5));
        m.set_number("shininess", 20);
        return m;
    }();
    const Material metal = [] {
        Material m = Material::of("metal");
        m.set_vec3("color", dvec3(0.9));
        m.set_number("d", 0.0);
        m.set_lobes({{0.5, 0.4}});
        return m;
    }();
    const SurfacePoint p = at({0, 0, 0}, {0.2, 1, 0.1}, {0.3, 1, 0.4});
    const dvec3 toward = glm::normalize(dvec3(0.1, 1, -0.2));
    const dvec3 normal = glm::normalize(dvec3(0.5, -1, 0.3));  // the rect faces the point obliquely
    const double cos_e = -glm::dot(toward, normal);
    for (const Material& material : {lambert(0.7), phong, metal})
        for (const LightType type : {LightType::rect, LightType::disk}) {
            double previous = 1.0;
            for (const double d : {25.0, 50.0, 100.0}) {
                const Light far = type == LightType::rect ? rect(d * toward, normal, 1.0, 0.6, 5.0)
                                                          : disk(d * toward, normal, 0.4, 5.0);
                const double area = shade_opaque(material, {far}, p).r;
                const double point = shade_opaque(material, {point_light(d * toward, 5.0 * cos_e)}, p).r;
                const double gap = std::fabs(area - point) / point;
                const std::string what = material.model_name() + " " + to_string(type) + " at " + std::to_string(d);
                EXPECT_LT(gap, 2e-3) << what;
                EXPECT_LT(gap, previous / 3) << what;  // as (size / d)^2
                previous = gap;
            }
        }
}

// ---- the limit of many small lights --------------------------------------------------------

// The rect as n x n directional lights at its cells' centres, each of scale L c dw.
std::vector<Light> as_many_lights(const Light& light, const dvec3& P, int n) {
    const RectFrame frame = rect_frame(light);
    const dvec3 L = radiance(light);
    std::vector<Light> lights;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const dvec3 q = light.position + ((i + 0.5) / n - 0.5) * light.size[0] * frame.side0 +
                            ((j + 0.5) / n - 0.5) * light.size[1] * frame.side1;
            const double r = glm::length(q - P);
            const dvec3 w = (q - P) / r;
            const double dw = emitter_area(light) / (n * n) * -glm::dot(w, light.normal) / (r * r);
            Light small = directional(w);
            small.intensity = 1.0;
            small.color = L * dw;
            lights.push_back(small);
        }
    return lights;
}

TEST(AreaLights, EveryModelTakesAnAreaLightAsTheLimitOfManySmallLights) {
    const Light light = rect({0, 2, 0}, {0, -1, 0}, 1.0, 0.8, 4.0);
    const SurfacePoint p = at({0, 0, 0}, {0, 1, 0}, {0.2, 1, 0.1});
    Material highlight = Material::of("highlight");
    highlight.set_vec3("color", {0.8, 0.3, 0.2});
    highlight.set_number("m", 20);
    Material phong = Material::of("phong");
    phong.set_vec3("kd", dvec3(0.4));
    phong.set_number("shininess", 30);
    for (const Material& material : {highlight, phong}) {
        const dvec3 area = shade_opaque(material, {light}, p);
        const double coarse = glm::length(shade_opaque(material, as_many_lights(light, p.P, 8), p) - area);
        const double fine = glm::length(shade_opaque(material, as_many_lights(light, p.P, 64), p) - area);
        EXPECT_LT(fine, coarse / 20) << material.model_name();  // the midpoint rule's h^2 (and 1 - s -> exp(-s))
        EXPECT_LT(fine, 1e-3) << material.model_name();
    }
}

TEST(AreaLights, AHighlightsShareOfWhiteIsTheExponentialOfItsIntegral) {
    // One bright narrow light: many small lights' product of (1 - s) tends to exp(-integral of s), not 1 - integral.
    Material m = Material::of("highlight");
    m.set_vec3("color", dvec3(0.0));
    m.set_number("d", 0.0);
    m.set_number("w", 1.0);
    m.set_number("m", 0.0);  // (R.V)^0 = 1: s integrates to w L dw over the light
    const Light light = rect({0, 2, 0}, {0, -1, 0}, 1.0, 1.0, 10.0);
    const SurfacePoint p = at({0, 0, 0}, {0, 1, 0});
    // s = w L dw integrates to the square's radiance 10 times its solid angle, 4 asin(1 / 17).
    const double s = 10.0 * 4 * std::asin(1.0 / 17.0);
    EXPECT_LE(relative(shade_opaque(m, {light}, p).r, 1 - std::exp(-s)), 1e-5);
}

// ---- every model under every new light ----------------------------------------------------

TEST(AreaLights, EveryModelUnderEveryAreaLightIsFiniteNonNegativeAndConverged) {
    Scene scene;
    Object ball;
    ball.center = {0, 0, 0};
    ball.radius = 1.0;
    scene.objects.push_back(ball);
    const SceneBvh occluders(scene);
    std::vector<Light> lights = {rect({0.5, 3, 0.5}, {-0.2, -1, -0.1}, 1.0, 0.5, 3.0), disk({2, 2, 2}, {-1, -1, -1}, 0.4, 2.0),
                                 sky(0.5)};
    const std::vector<SurfacePoint> points = {at({0, 1, 0}, {0, 1, 0}, {0, 1, 1}),
                                              at(glm::normalize(dvec3(1, 1, 1)), {1, 1, 1}, {0, 0.5, 1}),
                                              at({1, 0, 0}, {1, 0, 0}, {1, 0.2, 0.3})};
    int checked = 0;
    for (const std::string& name : model_table().names()) {
        const ModelSpec& model = model_table().get(name);
        if (model.family == Family::brdf) continue;  // no C++ twin
        const Material material = Material::of(name);
        for (Light light : lights)
            for (const bool shadow : {false, true}) {
                light.shadow = shadow;
                for (const SurfacePoint& p : points) {
                    AreaStats stats;
                    LightingOptions options{&occluders, {}, &stats};
                    const dvec3 c = material.model().family == Family::translucent
                                        ? shade_translucent_model(material, {light}, p, options).color
                                        : shade_opaque(material, {light}, p, dvec3(0.0), options);
                    for (int k = 0; k < 3; ++k) {
                        EXPECT_TRUE(std::isfinite(c[k])) << name;
                        EXPECT_GE(c[k], 0.0) << name;
                    }
                    EXPECT_EQ(stats.unconverged, 0) << name << " " << to_string(light.type);
                    ++checked;
                }
            }
    }
    EXPECT_GT(checked, 300);
}

// ---- shadows -----------------------------------------------------------------------------------

Scene ball_over_floor() {
    Scene scene;
    Object ball;
    ball.center = {0, 2, 0};
    ball.radius = 1.0;
    Object floor;
    floor.shape = Shape::plane;
    floor.center = {0, 0, 0};
    floor.axis = {0, 1, 0};
    floor.size = 20;
    scene.objects = {ball, floor};
    return scene;
}

TEST(AreaLights, DirectionalPointAndSpotLightsCastHardShadows) {
    const Scene scene = ball_over_floor();
    const SceneBvh occluders(scene);
    Light spot = point_light({0, 5, 0});
    spot.type = LightType::spot;
    spot.spot_direction = {0, -1, 0};
    for (Light light : {directional({0, 1, 0}), point_light({0, 5, 0}), spot}) {
        const SurfacePoint under = at({0.5, 0, 0}, {0, 1, 0}), beside = at({3, 0, 0}, {0, 1, 0});
        const LightingOptions options{&occluders, {}, nullptr};
        EXPECT_GT(shade_opaque(lambert(), {light}, under, dvec3(0.0), options).r, 0.0) << "no shadow asked";
        light.shadow = true;
        EXPECT_EQ(shade_opaque(lambert(), {light}, under, dvec3(0.0), options).r, 0.0) << to_string(light.type);
        EXPECT_GT(shade_opaque(lambert(), {light}, beside, dvec3(0.0), options).r, 0.0) << to_string(light.type);
        EXPECT_EQ(shade_opaque(lambert(), {light}, beside, dvec3(0.0), options).r,
                  shade_opaque(lambert(), {light}, beside).r);
    }
}

TEST(AreaLights, AShadowedLightKeepsItsAmbient) {
    const Scene scene = ball_over_floor();
    const SceneBvh occluders(scene);
    Light light = directional({0, 1, 0});
    light.shadow = true;
    light.ambient = dvec3(0.25);
    Material material = lambert();
    material.set_vec3("ka", dvec3(1.0));
    const double got = shade_opaque(material, {light}, at({0, 0, 0}, {0, 1, 0}), dvec3(0.0), {&occluders, {}, nullptr}).r;
    EXPECT_DOUBLE_EQ(got, 0.25);  // a_l ambient K_amb: the light's own share is gone
}

TEST(AreaLights, InTheUmbraOfASmallRectALambertPointIsExactlyBlack) {
    const Scene scene = ball_over_floor();
    const SceneBvh occluders(scene);
    Light light = rect({0, 5, 0}, {0, -1, 0}, 0.3, 0.3, 5.0);
    light.shadow = true;
    for (const double x : {0.0, 0.2, -0.3})
        EXPECT_EQ(shade_opaque(lambert(), {light}, at({x, 0, 0.1}, {0, 1, 0}), dvec3(0.0), {&occluders, {}, nullptr}).r, 0.0);
}

TEST(AreaLights, ThePenumbraRisesMonotonicallyFromUmbraToFullLight) {
    const Scene scene = ball_over_floor();
    const SceneBvh occluders(scene);
    Light light = rect({0, 5, 0}, {0, -1, 0}, 1.5, 1.5, 5.0);
    const double tolerance = AreaQuadrature{}.shadow_tolerance;
    double previous = -1.0;
    for (double x = 0.0; x <= 4.0; x += 0.1) {
        light.shadow = true;
        const double lit = shade_opaque(lambert(), {light}, at({x, 0, 0}, {0, 1, 0}), dvec3(0.0), {&occluders, {}, nullptr}).r;
        light.shadow = false;
        const double open = shade_opaque(lambert(), {light}, at({x, 0, 0}, {0, 1, 0})).r;
        // The shadow's share of the light only falls, from all of it to none.
        const double share = lit / open;
        EXPECT_GE(share, previous - 2 * tolerance) << x;
        EXPECT_LE(share, 1.0 + 2 * tolerance) << x;
        previous = share;
    }
    EXPECT_NEAR(previous, 1.0, 1e-12);  // out of the penumbra: all of it
}

// The part of convex polygon `poly` (in a plane y = const) inside convex `clip`, by Sutherland-Hodgman in x-z.
std::vector<dvec3> clip_convex(std::vector<dvec3> poly, const std::vector<dvec3>& clip) {
    double orientation = 0.0;
    for (std::size_t i = 0; i < clip.size(); ++i)
        orientation += clip[i].x * clip[(i + 1) % clip.size()].z - clip[(i + 1) % clip.size()].x * clip[i].z;
    for (std::size_t e = 0; e < clip.size() && !poly.empty(); ++e) {
        const dvec3 a = clip[e], b = clip[(e + 1) % clip.size()];
        const auto inside = [&](const dvec3& p) {
            const double cross = (b.x - a.x) * (p.z - a.z) - (b.z - a.z) * (p.x - a.x);
            return orientation > 0 ? cross : -cross;
        };
        std::vector<dvec3> kept;
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const dvec3 p = poly[i], q = poly[(i + 1) % poly.size()];
            const double sp = inside(p), sq = inside(q);
            if (sp >= 0) kept.push_back(p);
            if ((sp >= 0) != (sq >= 0)) kept.push_back(p + (sp / (sp - sq)) * (q - p));
        }
        poly = kept;
    }
    return poly;
}

TEST(AreaLights, ThePenumbraOfASquarePlateIsLambertsFormulaOnWhatStaysInView) {
    // A 1 x 1 rect at height 3, a 0.6 x 0.6 plate at height 1.5 between it and the floor.
    Light light = rect({0, 3, 0}, {0, -1, 0}, 1.0, 1.0, 3.0);
    light.shadow = true;
    Scene scene;
    Object plate;
    plate.shape = Shape::plane;
    plate.center = {0, 1.5, 0};
    plate.axis = {0, 1, 0};
    plate.size = 0.6;
    scene.objects = {plate};
    const SceneBvh occluders(scene);
    const std::vector<dvec3> emitter = {{-0.5, 3, -0.5}, {0.5, 3, -0.5}, {0.5, 3, 0.5}, {-0.5, 3, 0.5}};
    const std::vector<dvec3> blocker = {{-0.3, 1.5, -0.3}, {0.3, 1.5, -0.3}, {0.3, 1.5, 0.3}, {-0.3, 1.5, 0.3}};
    const LightingOptions options{&occluders, {}, nullptr};
    double worst = 0.0;
    for (int k = 0; k <= 40; ++k) {
        const dvec3 P(-1.5 + 3.0 * k / 40, 0, 0.13);
        // The plate as seen from P on the emitter's plane, and the part of the emitter it hides.
        std::vector<dvec3> shadow;
        for (const dvec3& c : blocker) shadow.push_back(P + (c - P) * ((3 - P.y) / (c.y - P.y)));
        const std::vector<dvec3> hidden = clip_convex(emitter, shadow);
        const double in_view = polygon_projected_solid_angle(emitter, P, {0, 1, 0}) -
                               (hidden.size() >= 3 ? polygon_projected_solid_angle(hidden, P, {0, 1, 0}) : 0.0);
        const double got = shade_opaque(lambert(), {light}, at(P, {0, 1, 0}), dvec3(0.0), options).r;
        worst = std::max(worst, std::fabs(got - 3.0 * in_view));  // radiance 3 / 1
    }
    EXPECT_LE(worst, 2 * options.quadrature.shadow_tolerance);
}

TEST(AreaLights, UnderASquarePlateTheSkyIsPiLessThePlatesProjectedSolidAngle) {
    Light light = sky();
    light.shadow = true;
    Scene scene;
    Object plate;
    plate.shape = Shape::plane;
    plate.center = {0.2, 1, -0.1};
    plate.axis = {0, 1, 0};
    plate.size = 3;
    scene.objects = {plate};
    const SceneBvh occluders(scene);
    const std::vector<dvec3> square = {{-1.3, 1, -1.6}, {1.7, 1, -1.6}, {1.7, 1, 1.4}, {-1.3, 1, 1.4}};
    for (const dvec3& P : {dvec3(0, 0, 0), dvec3(1.2, 0, 0.9), dvec3(3, 0, 0)}) {
        const double open = kPi - polygon_projected_solid_angle(square, P, {0, 1, 0});
        const double got = shade_opaque(lambert(), {light}, at(P, {0, 1, 0}), dvec3(0.0), {&occluders, {}, nullptr}).r;
        EXPECT_LE(std::fabs(got - open / kPi), 2 * AreaQuadrature{}.shadow_tolerance) << P.x;  // L = 1 / pi
    }
}

TEST(AreaLights, UnderASphereTheSkyLosesTheSpheresViewFactor) {
    // A sphere of radius r at distance d, beta off the normal and wholly above the
    // horizon, has projected solid angle pi (r / d)^2 cos(beta): a unit sky gives 1 - (r / d)^2 cos(beta).
    Light light = sky();
    light.shadow = true;
    Scene scene;
    Object ball;
    ball.center = {0, 2, 0};
    ball.radius = 0.8;
    scene.objects = {ball};
    const SceneBvh occluders(scene);
    for (const double x : {0.0, 0.7, 1.5}) {
        const dvec3 P(x, 0, 0), to_centre = ball.center - P;
        const double d = glm::length(to_centre), cos_beta = to_centre.y / d;
        ASSERT_LT(std::acos(cos_beta) + std::asin(ball.radius / d), kPi / 2) << x;  // wholly above the horizon
        const double open = 1 - ball.radius * ball.radius / (d * d) * cos_beta;
        const double got = shade_opaque(lambert(), {light}, at(P, {0, 1, 0}), dvec3(0.0), {&occluders, {}, nullptr}).r;
        EXPECT_LE(std::fabs(got - open), 2 * AreaQuadrature{}.shadow_tolerance) << x;
        EXPECT_LT(got, 1.0 - 0.05) << x;  // the sphere's share is far above the tolerance
    }
}

// ---- whole images --------------------------------------------------------------------------------

TEST(AreaLights, AReferenceImageWithEveryNewLightIsFiniteConvergedAndShadowed) {
    Scene scene = ball_over_floor();
    scene.display = {48, 30, 5, false};
    scene.camera.position = {0, 4, 9};
    scene.camera.target = {0, 1, 0};
    scene.objects[0].material = Material::of("highlight");
    scene.objects[1].material = lambert(0.7);
    Light key = rect({0, 5, 0}, {0, -1, 0}, 1.0, 1.0, 4.0);
    key.shadow = true;
    Light fill = disk({4, 3, 3}, {-1, -1, -1}, 0.5, 1.0);
    Light ambient = sky(0.2);
    ambient.shadow = true;
    scene.lights = {key, fill, ambient};
    AreaStats stats;
    const ReferenceImage image = render_reference(scene, {}, &stats);
    for (const double v : image.rgb) {
        ASSERT_TRUE(std::isfinite(v));
        ASSERT_GE(v, 0.0);
    }
    EXPECT_EQ(stats.unconverged, 0);
    EXPECT_GT(stats.integrals, 0);
    // The same scene without shadows is nowhere darker, and somewhere much lighter.
    const ReferenceImage lit = [&] {
        Scene open = scene;
        for (Light& light : open.lights) light.shadow = false;
        return render_reference(open);
    }();
    double darker = 0.0;
    for (std::size_t i = 0; i < lit.rgb.size(); ++i) {
        EXPECT_LE(image.rgb[i], lit.rgb[i] + 2e-4);  // a shadow only takes light away
        darker = std::max(darker, lit.rgb[i] - image.rgb[i]);
    }
    EXPECT_GT(darker, 0.1);
}

TEST(AreaLights, ASphereShadowsExactlyTheFloorPixelsWhoseWayToTheLightItMeets) {
    // Floor pixels are dark exactly where the ray from their point along L passes within r of the centre.
    Scene scene = ball_over_floor();
    scene.display = {64, 40, 5, false};
    scene.camera.position = {0, 6, 7};
    scene.camera.target = {0, 0, 0};
    scene.objects[1].material = lambert(1.0);
    scene.objects[0].material = lambert(1.0);
    Light light = directional({0.45, 1, 0.3});
    light.shadow = true;
    scene.lights = {light};
    const ReferenceImage image = render_reference(scene);
    const Object& ball = scene.objects[0];
    int dark = 0, lit = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const Ray ray = camera_ray(scene.camera, image.width, image.height, x, y);
            double t_ball = 0.0;
            if (intersect_sphere(ray, ball.center, ball.radius, &t_ball) || !(ray.dir.y < 0.0)) continue;
            const dvec3 P = ray.origin + (-ray.origin.y / ray.dir.y) * ray.dir;  // on the floor y = 0
            if (std::fabs(P.x) > 9.0 || std::fabs(P.z) > 9.0) continue;
            const dvec3 oc = ball.center - P;
            const double along = glm::dot(oc, light.direction);
            const double miss = glm::length(oc - along * light.direction) - ball.radius;
            if (std::fabs(miss) < 1e-9) continue;  // on the shadow's edge
            const bool shadowed = along > 0.0 && miss < 0.0;
            const double got = image.rgb[3 * (std::size_t(y) * image.width + x)];
            if (shadowed) {
                EXPECT_EQ(got, 0.0) << x << " " << y;
                ++dark;
            } else {
                EXPECT_NEAR(got, light.direction.y, 1e-12) << x << " " << y;  // kd N.L
                ++lit;
            }
        }
    EXPECT_GT(dark, 30);
    EXPECT_GT(lit, 300);
}

TEST(AreaLights, WhereNothingBlocksALightItsShadowChangesNothing) {
    // One sphere cannot shadow itself: with every light type casting shadows the image is the same.
    Scene scene;
    Object ball;
    ball.center = {0, 0, 0};
    ball.radius = 1.0;
    ball.material = Material::of("highlight");
    scene.objects = {ball};
    scene.display = {40, 40, 5, false};
    scene.camera.position = {0, 1, 4};
    scene.camera.target = {0, 0, 0};
    Light spot = point_light({1, 3, 2}, 4.0);
    spot.type = LightType::spot;
    spot.spot_direction = glm::normalize(dvec3(-1, -3, -2));
    scene.lights = {directional({1, 1, 1}), point_light({-2, 1, 2}, 3.0), spot,
                    rect({0, 3, 1}, {0, -1, -0.3}, 1.0, 0.5, 2.0), disk({-2, 2, 2}, {1, -1, -1}, 0.4, 2.0), sky(0.3)};
    const ReferenceImage open = render_reference(scene);
    for (Light& light : scene.lights) light.shadow = true;
    AreaStats stats;
    const ReferenceImage shadowed = render_reference(scene, AreaQuadrature{}, &stats);
    EXPECT_GT(stats.rays, 0);  // the shadows were tested
    double worst = 0.0;
    for (std::size_t i = 0; i < open.rgb.size(); ++i) worst = std::max(worst, std::fabs(open.rgb[i] - shadowed.rgb[i]));
    EXPECT_LE(worst, 2 * AreaQuadrature{}.shadow_tolerance);
    // The point lights alone: the same to the last bit.
    scene.lights.resize(3);
    const ReferenceImage hard = render_reference(scene);
    for (Light& light : scene.lights) light.shadow = false;
    EXPECT_EQ(hard.rgb, render_reference(scene).rgb);
}

}  // namespace
}  // namespace m3055::ref
