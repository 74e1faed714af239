// Rect, disk and sky lights and shadows on the GPU (glsl/common/area_lights.glsl,
// shadows.glsl) against the CPU reference (reference/lit_point.h), which
// integrates the emitters adaptively and traces visibility in double: every
// model family under every new light, with and without shadows, on a floor
// (a mesh plane), a sphere and a cube, at the render's sampling
// (passes/light_uniforms.h: kRenderSampling). On interior pixels:
//   - no NaN or Inf;
//   - unbiased: the mean of gpu - ref within 3e-4 (a missed occluder, a
//     wrong pdf or a lost sample shows here);
//   - every light's raw error within docs/spec.md's target: <= 5e-3, <= 1e-2
//     with a shadow (its largest errors are in the soft shadows);
//   - rects and disks, shadowed or not, and the unshadowed sky: docs/spec.md's
//     target, >= 99.5 % of pixels on the same display level and none more than
//     one off;
//   - the sky's shadow (what the objects block, its Lambert part exact for
//     spheres and boxes): none more than one off, >= 99.3 % on the same level
//     and mean |diff| <= 1e-4 (not yet 99.5 % for every family: metal 99.43 %).
// docs/lights.md has the measured errors of each case.
#include "gpu_compare.h"
#include "sanitized.h"

#include "frame/renderer.h"
#include "scene/load.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>
#include <ostream>
#include <string>
#include <vector>

namespace m3055 {
namespace {

constexpr int kMaxLevelDiff = 1;
constexpr double kBias = 3e-4;
constexpr double kMeanDiff = 1e-3;
constexpr double kSameLevelShare = 0.995;     // docs/spec.md's target
// Raw, docs/spec.md's target: unshadowed 1.3e-5-4.2e-3 (disk metal), shadowed 0.0036-0.0098
// (disk principled; the sky's 0.0042-0.0086).
constexpr double kMaxDiff = 5e-3;
constexpr double kShadowMaxDiff = 1e-2;
// The sky's shadow: what the objects block drawn about them, its Lambert part exact for the
// sphere and the cube (glsl/common/sky_occluders.glsl): 99.43-99.72 % on the same level, mean
// |diff| 3.7e-5-6.8e-5, max 0.0042-0.0086 (sampled alone: 93.4-94.1 %, 6.3e-4-7.1e-4; drawn from
// the whole sky: 81 %, 2e-3). Part of what is left is the reference's own error (its shadow
// tolerance, 1e-4: against one 100 x tighter, 99.47-99.76 %, mean signed +2e-6 against -1.3e-5).
constexpr double kSkyShadowMeanDiff = 1e-4;
constexpr double kSkyShadowSameLevelShare = 0.993;

struct LightCase {
    std::string name;
    nlohmann::json light;
};

struct MaterialCase {
    std::string name;
    nlohmann::json material;
};

const LightCase kLights[] = {
    {"rect", {{"type", "rect"}, {"position", {1.5, 2.5, 1.5}}, {"normal", {-0.5, -0.7, -0.5}},
              {"size", {1.2, 0.8}}, {"intensity", 4.0}, {"color", {1.0, 0.9, 0.8}}}},
    {"disk", {{"type", "disk"}, {"position", {-2.0, 1.5, 1.5}}, {"normal", {0.8, -0.4, -0.5}},
              {"radius", 0.6}, {"intensity", 3.0}}},
    {"sky", {{"type", "sky"}, {"intensity", 0.8}, {"color", {0.7, 0.8, 1.0}}}},
};

const MaterialCase kMaterials[] = {
    {"highlight", {{"model", "highlight"}, {"color", {0.8, 0.3, 0.2}}, {"d", 0.5}, {"w", 0.8}, {"m", 20}}},
    {"metal", {{"model", "metal"}, {"color", {0.9, 0.7, 0.3}}}},
    {"phong", {{"model", "phong"}, {"kd", {0.5, 0.4, 0.3}}, {"ks", {0.4, 0.4, 0.4}}, {"shininess", 40}}},
    {"microfacet", {{"model", "microfacet"}, {"kd", {0.3, 0.3, 0.5}}, {"ks", {0.5, 0.5, 0.5}}}},
    {"principled", {{"model", "principled"}, {"base_color", {0.8, 0.5, 0.3}}, {"roughness", 0.4}}},
};

// A floor, a sphere and a cube under one light; `shadow` on it.
Scene lit_scene(const LightCase& light, const MaterialCase& material, bool shadow) {
    nlohmann::json floor = {{"model", "lambert"}, {"kd", {0.6, 0.6, 0.6}}};
    nlohmann::json l = light.light;
    l["shadow"] = shadow;
    nlohmann::json doc = {
        {"display", {{"width", 128}, {"height", 80}, {"bits", 5}}},
        {"background", {0.05, 0.05, 0.08}},
        {"camera", {{"projection", "perspective"}, {"position", {0, 2.2, 5.5}}, {"target", {0, 0.5, 0}},
                    {"up", {0, 1, 0}}, {"fov_y_deg", 35}}},
        {"lights", {l}},
        {"objects",
         {{{"shape", "plane"}, {"center", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"size", 8}, {"material", floor}},
          {{"shape", "sphere"}, {"center", {-0.7, 0.6, 0}}, {"radius", 0.6}, {"material", material.material}},
          {{"shape", "cube"}, {"center", {0.9, 0.45, -0.2}}, {"size", 0.9}, {"rotation_deg", {0, 30, 0}},
           {"material", material.material}}}}};
    return scene_from_json(doc, "area_lights_gpu_test.json", LoadContext::trusted());
}

using Case = std::tuple<int, int, bool>;

std::string case_name(const Case& c) {
    const auto [l, m, shadow] = c;
    return kLights[l].name + "_" + kMaterials[m].name + (shadow ? "_shadowed" : "_unshadowed");
}

class AreaLightOnTheGpu : public ::testing::TestWithParam<Case> {};

TEST_P(AreaLightOnTheGpu, MatchesTheReference) {
    const auto [l, m, shadow] = GetParam();
    const test::Comparison c = test::compare_gpu_with_reference(lit_scene(kLights[l], kMaterials[m], shadow));
    std::cout << case_name(GetParam()) << ": " << c.describe() << "\n";  // docs/lights.md's table
    SCOPED_TRACE(c.describe());
    EXPECT_EQ(c.nonfinite_values, 0);
    EXPECT_LE(c.max_level_diff, kMaxLevelDiff);
    EXPECT_LE(std::abs(c.mean_signed_diff), kBias);
    const bool sky = kLights[l].name == "sky";
    EXPECT_LE(c.max_abs_diff, shadow ? kShadowMaxDiff : kMaxDiff);
    if (sky && shadow) {
        EXPECT_LE(c.mean_abs_diff, kSkyShadowMeanDiff);
        EXPECT_GE(c.same_level_share, kSkyShadowSameLevelShare);
    } else {
        EXPECT_LE(c.mean_abs_diff, kMeanDiff);
        EXPECT_GE(c.same_level_share, kSameLevelShare);
    }
}

// The glossy floors' tests hold the shader's sampling of sharp lobes under the sky; their host
// code (scene, uniforms, reference) is the matrix's, which the sanitized suite runs, and under
// the sanitizers the reference of a sharp lobe took minutes (a mirror floor: 214 s).
constexpr const char* kShaderNumericsOnly = "the shader's numerics, the matrix's host code: Release suite only";

// A 64 x 40 scene of `objects` under `sky`, seen by `camera`.
Scene sky_scene(const nlohmann::json& camera, const nlohmann::json& objects, const nlohmann::json& sky,
                const std::string& name) {
    const nlohmann::json doc = {{"display", {{"width", 64}, {"height", 40}, {"bits", 5}}},
                                {"background", {0.05, 0.05, 0.08}},
                                {"camera", camera},
                                {"lights", {sky}},
                                {"objects", objects}};
    return scene_from_json(doc, name, LoadContext::trusted());
}

// The same under the shadowed sky of the matrix.
Scene shadowed_sky_scene(const nlohmann::json& camera, const nlohmann::json& objects, const std::string& name) {
    const nlohmann::json sky = {{"type", "sky"}, {"intensity", 0.8}, {"color", {0.7, 0.8, 1.0}}, {"shadow", true}};
    return sky_scene(camera, objects, sky, name);
}

// A floor under a metal cylinder (capped: its mesh a prism, whose silhouette has a closed
// form) under the shadowed sky: what it blocks is exact for the floor's Lambert term, so the
// floor is at docs/spec.md's target (99.7 % on the same level, mean |diff| 3.0e-5; the
// cylinder drawn about with samples alone, as a torus still is: 92.4 %, 8.0e-4).
TEST(SkyShadowOnTheGpu, ACylindersPrismTakesItsExactPartFromTheFloor) {
    const nlohmann::json camera = {{"projection", "perspective"}, {"position", {0, 2.2, 5.5}}, {"target", {0, 0.5, 0}},
                                   {"up", {0, 1, 0}}, {"fov_y_deg", 35}};
    const nlohmann::json objects = {
        {{"shape", "plane"}, {"center", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"size", 8},
         {"material", {{"model", "lambert"}, {"kd", {0.6, 0.6, 0.6}}}}},
        {{"shape", "cylinder"}, {"center", {0.2, 0.7, 0}}, {"axis", {0, 1, 0}}, {"radius", 0.5}, {"height", 1.4},
         {"material", kMaterials[1].material}}};
    const test::Comparison c = test::compare_gpu_with_reference(shadowed_sky_scene(camera, objects, "cylinder.json"));
    std::cout << "sky over a cylinder: " << c.describe() << "\n";
    SCOPED_TRACE(c.describe());
    EXPECT_EQ(c.nonfinite_values, 0);
    EXPECT_LE(c.max_level_diff, kMaxLevelDiff);
    EXPECT_LE(c.max_abs_diff, kShadowMaxDiff);
    EXPECT_LE(c.mean_abs_diff, kSkyShadowMeanDiff);
    EXPECT_GE(c.same_level_share, kSameLevelShare);
}

// The shadowed sky over eight objects (as many as are drawn about: three spheres, two cubes,
// a cylinder, a torus, the floor) of three families. Every sample of what they block walks
// every object, and llvmpipe leaves all loops of a pixel after 65 535 iterations without a
// word: a lost walk leaves light that should have been taken away, pixels too bright. A
// denser estimate of the silhouettes' overlap over all of them did that (95.7 % on the same
// level, 4 levels off, mean diff +1.9e-4; measured 97.6 %, 1, -1.3e-5).
TEST(SkyShadowOnTheGpu, EightObjectsStayWithinTheLoopLimit) {
    const nlohmann::json highlight = kMaterials[0].material, metal = kMaterials[1].material;
    const nlohmann::json camera = {{"projection", "perspective"}, {"position", {0, 2.6, 7.5}}, {"target", {0, 0.5, 0}},
                                   {"up", {0, 1, 0}}, {"fov_y_deg", 38}};
    const nlohmann::json objects = {
        {{"shape", "plane"}, {"center", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"size", 12},
         {"material", {{"model", "lambert"}, {"kd", {0.6, 0.6, 0.6}}}}},
        {{"shape", "sphere"}, {"center", {-2.6, 0.5, 0}}, {"radius", 0.5}, {"material", highlight}},
        {{"shape", "sphere"}, {"center", {-1.2, 0.4, 1.0}}, {"radius", 0.4}, {"material", metal}},
        {{"shape", "sphere"}, {"center", {2.4, 0.6, -0.8}}, {"radius", 0.6}, {"material", highlight}},
        {{"shape", "cube"}, {"center", {-0.2, 0.45, -0.5}}, {"size", 0.9}, {"rotation_deg", {0, 30, 0}},
         {"material", highlight}},
        {{"shape", "cube"}, {"center", {1.0, 0.3, 1.0}}, {"size", 0.6}, {"rotation_deg", {0, 10, 0}},
         {"material", metal}},
        {{"shape", "cylinder"}, {"center", {0.9, 0.6, -1.2}}, {"axis", {0, 1, 0}}, {"radius", 0.4}, {"height", 1.2},
         {"material", metal}},
        {{"shape", "torus"}, {"center", {2.6, 0.22, 1.0}}, {"axis", {0, 1, 0}}, {"major_radius", 0.5},
         {"minor_radius", 0.2}, {"material", highlight}}};
    const test::Comparison c =
        test::compare_gpu_with_reference(shadowed_sky_scene(camera, objects, "eight_objects.json"));
    std::cout << "sky over eight objects: " << c.describe() << "\n";
    SCOPED_TRACE(c.describe());
    EXPECT_EQ(c.nonfinite_values, 0);
    EXPECT_LE(c.max_level_diff, kMaxLevelDiff);
    EXPECT_LE(std::abs(c.mean_signed_diff), 5e-5);
    EXPECT_GE(c.same_level_share, 0.97);
}

// Two cylinders side by side under the shadowed sky: from each one's side the other stands
// across its horizons (up's and N's), and its prism's outline is clipped to both
// (glsl/common/sky_occluders.glsl: ClippedOutline), so the Lambert term of what it blocks
// is exact there too (drawn about with samples alone, as where only a prism wholly above
// both horizons had its closed form: 98.2 % on the same level, max |diff| 0.024, mean
// 2.2e-4; measured 99.6 %, 0.0014, 4.4e-5).
TEST(SkyShadowOnTheGpu, ANeighboursPrismIsClippedToBothHorizons) {
    const nlohmann::json camera = {{"projection", "perspective"}, {"position", {0, 1.6, 4.5}}, {"target", {0, 0.6, 0}},
                                   {"up", {0, 1, 0}}, {"fov_y_deg", 30}};
    const nlohmann::json objects = {
        {{"shape", "plane"}, {"center", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"size", 8},
         {"material", {{"model", "lambert"}, {"kd", {0.6, 0.6, 0.6}}}}},
        {{"shape", "cylinder"}, {"center", {-0.75, 0.6, 0}}, {"axis", {0, 1, 0}}, {"radius", 0.5}, {"height", 1.2},
         {"material", {{"model", "lambert"}, {"kd", {0.8, 0.5, 0.3}}}}},
        {{"shape", "cylinder"}, {"center", {0.75, 0.6, 0}}, {"axis", {0, 1, 0}}, {"radius", 0.5}, {"height", 1.2},
         {"material", {{"model", "lambert"}, {"kd", {0.3, 0.5, 0.8}}}}}};
    const test::Comparison c =
        test::compare_gpu_with_reference(shadowed_sky_scene(camera, objects, "two_cylinders.json"));
    std::cout << "sky between two cylinders: " << c.describe() << "\n";
    SCOPED_TRACE(c.describe());
    EXPECT_EQ(c.nonfinite_values, 0);
    EXPECT_LE(c.max_level_diff, kMaxLevelDiff);
    EXPECT_LE(c.max_abs_diff, kMaxDiff);
    EXPECT_LE(c.mean_abs_diff, 1e-4);
    EXPECT_GE(c.same_level_share, kSameLevelShare);
}

// Two cylinders sunk into the floor, one tilted: from the floor's points (up's horizon is
// N's) each crosses the horizon, and its outline's chord along it closes the clipped
// polygon (one plane's test drops it, the other's takes its crossings again). Measured
// 99.8 % on the same level, max |diff| 0.0024, mean 4.9e-5 (where only a prism wholly above
// both horizons had its closed form: 84.3 %, 2 levels off, 0.043, 2.4e-3).
TEST(SkyShadowOnTheGpu, CylindersSunkIntoTheFloorAreClippedToItsHorizon) {
    const nlohmann::json camera = {{"projection", "perspective"}, {"position", {0, 1.6, 4.5}}, {"target", {0, 0.6, 0}},
                                   {"up", {0, 1, 0}}, {"fov_y_deg", 30}};
    const nlohmann::json lambert = {{"model", "lambert"}, {"kd", {0.6, 0.6, 0.6}}};
    const nlohmann::json objects = {
        {{"shape", "plane"}, {"center", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"size", 8}, {"material", lambert}},
        {{"shape", "cylinder"}, {"center", {-0.75, 0.2, 0}}, {"axis", {0, 1, 0}}, {"radius", 0.5}, {"height", 1.2},
         {"material", lambert}},
        {{"shape", "cylinder"}, {"center", {0.75, 0.5, 0}}, {"axis", {0.4, 1, 0.2}}, {"radius", 0.5}, {"height", 1.2},
         {"material", lambert}}};
    const test::Comparison c = test::compare_gpu_with_reference(shadowed_sky_scene(camera, objects, "sunk.json"));
    std::cout << "sky over sunk cylinders: " << c.describe() << "\n";
    SCOPED_TRACE(c.describe());
    EXPECT_EQ(c.nonfinite_values, 0);
    EXPECT_LE(c.max_level_diff, kMaxLevelDiff);
    EXPECT_LE(c.max_abs_diff, kMaxDiff);
    EXPECT_LE(c.mean_abs_diff, 1e-4);
    EXPECT_GE(c.same_level_share, kSameLevelShare);
}

// A cylinder of few sides, close up, under the shadowed sky: its smooth normals lean up to
// 180 / n degrees from their faces, so each face blocks the lune of the sky above N's
// horizon and below the face's plane (glsl/common/sky_occluders.glsl: prism_own_face),
// drawn from the lune with its Lambert part exact. Drawn from the hemisphere, few samples
// met it: noisy facets, a principled lobe's estimate below zero (6 sides: 87.1 % on the
// same level, 8 levels off, mean |diff| 3.0e-3; 12 sides: 96.2 %, 5.5e-4; measured 98.6 %
// and 99.1 %, 1.3e-4 and 1.0e-4). The largest error is a pixel on an edge between two faces
// that the raster and the reference's ray give to different faces (0.045 at 6 sides, the
// same before): 2 levels there.
TEST(SkyShadowOnTheGpu, AFewSidedCylindersFacesBlockTheirOwnLune) {
    const nlohmann::json camera = {{"projection", "perspective"}, {"position", {0, 2.4, 7.5}},
                                   {"target", {-1.7, 0.85, 0.3}}, {"up", {0, 1, 0}}, {"fov_y_deg", 7}};
    for (const int sides : {6, 12}) {
        const nlohmann::json objects = {
            {{"shape", "plane"}, {"center", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"size", 14},
             {"material", {{"model", "lambert"}, {"kd", {0.6, 0.6, 0.6}}}}},
            {{"shape", "cylinder"}, {"center", {-1.7, 0.8, 0.3}}, {"axis", {1, 0, 0}}, {"radius", 0.35},
             {"height", 1.6}, {"segments", sides},
             {"material", {{"model", "principled"}, {"base_color", {0.2, 0.45, 0.85}}, {"roughness", 0.4}}}}};
        const test::Comparison c =
            test::compare_gpu_with_reference(shadowed_sky_scene(camera, objects, "few_sides.json"));
        std::cout << "sky on a " << sides << "-sided cylinder: " << c.describe() << "\n";
        SCOPED_TRACE(std::to_string(sides) + " sides: " + c.describe());
        EXPECT_EQ(c.nonfinite_values, 0);
        EXPECT_LE(c.max_level_diff, 2);
        EXPECT_LE(std::abs(c.mean_signed_diff), kBias);
        EXPECT_LE(c.mean_abs_diff, 2e-4);
        EXPECT_GE(c.same_level_share, 0.98);
    }
}

// A glossy principled floor (roughness 0.05) with a sphere and a cylinder under the shadowed
// sky: two objects, drawn about densely, whose mirror images in the floor are most of what
// they block there. Drawn from their cones alone, the images were missing and a sample that
// met the lobe's peak drew pixels far below zero (a student's scene at 128 x 80: down to
// -5.5, 6 levels off); now a sharp lobe draws its own samples of the blocked part. Measured
// (interior pixels): 95.8 % on the same level, 1 level at most, max |diff| 0.020.
TEST(SkyShadowOnTheGpu, AGlossyFloorMirrorsTwoObjects) {
    if (test::kSanitized) GTEST_SKIP() << kShaderNumericsOnly;
    const nlohmann::json camera = {{"projection", "perspective"}, {"position", {0.5, 1.8, 6}}, {"target", {0, 0.5, 0}},
                                   {"up", {0, 1, 0}}, {"fov_y_deg", 38}};
    const nlohmann::json objects = {
        {{"shape", "plane"}, {"center", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"size", 10},
         {"material", {{"model", "principled"}, {"base_color", {0.35, 0.35, 0.35}}, {"roughness", 0.05}}}},
        {{"shape", "sphere"}, {"center", {-1.5, 0.6, 0.3}}, {"radius", 0.6},
         {"material", {{"model", "principled"}, {"base_color", {0.8, 0.2, 0.2}}, {"roughness", 0.5}}}},
        {{"shape", "cylinder"}, {"center", {0.6, 0.5, -0.3}}, {"axis", {0, 1, 0}}, {"radius", 0.45}, {"height", 1.0},
         {"material", {{"model", "principled"}, {"base_color", {0.2, 0.4, 0.85}}, {"roughness", 1.0}}}}};
    const test::Comparison c = test::compare_gpu_with_reference(shadowed_sky_scene(camera, objects, "mirror.json"));
    std::cout << "sky mirrored in a glossy floor: " << c.describe() << "\n";
    SCOPED_TRACE(c.describe());
    EXPECT_EQ(c.nonfinite_values, 0);
    EXPECT_LE(c.max_level_diff, kMaxLevelDiff);
    EXPECT_LE(c.max_abs_diff, 0.03);
    EXPECT_LE(std::abs(c.mean_signed_diff), kBias);
}

// Every object principled, the floor too: three cylinders 0.05 apart and a sphere beside them
// under the shadowed sky. At the foot of the objects V's mirror direction points into them,
// and the floor's grazing Fresnel lobe is most of what they block; more objects than are
// drawn about densely, so the blocked part also draws from the lobe
// (glsl/common/sky_occluders.glsl: occluder_techniques). Drawn from the objects' cones
// alone, the interior pixels: max |diff| 0.027, mean signed -5.1e-5 (taken away too much;
// all pixels, the objects' feet too: 2 levels off, 0.062; at 128 x 80, 3 levels, 0.076 and
// pixels below zero). Measured: 0.0125, +3.3e-6 (all pixels: 1 level, 0.017).
TEST(SkyShadowOnTheGpu, AFloorsLobeAtTheFootOfFourObjectsIsDrawnFromTheLobe) {
    if (test::kSanitized) GTEST_SKIP() << kShaderNumericsOnly;
    const nlohmann::json camera = {{"projection", "perspective"}, {"position", {0, 2.4, 7.5}}, {"target", {0, 0.55, 0}},
                                   {"up", {0, 1, 0}}, {"fov_y_deg", 32}};
    auto principled = [](double r, double g, double b, double roughness) {
        return nlohmann::json{{"model", "principled"}, {"base_color", {r, g, b}}, {"roughness", roughness}};
    };
    auto cylinder = [&](double x, const nlohmann::json& material) {
        return nlohmann::json{{"shape", "cylinder"}, {"center", {x, 0.7, 0}}, {"axis", {0, 1, 0}}, {"radius", 0.5},
                              {"height", 1.4}, {"material", material}};
    };
    const nlohmann::json objects = {
        {{"shape", "plane"}, {"center", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"size", 14},
         {"material", principled(0.5, 0.5, 0.5, 0.5)}},
        cylinder(-1.6, principled(0.2, 0.5, 0.8, 0.3)),
        cylinder(-0.55, principled(0.5, 0.5, 0.5, 0.3)),
        cylinder(0.5, principled(0.8, 0.5, 0.2, 0.3)),
        {{"shape", "sphere"}, {"center", {1.75, 0.7, 0.2}}, {"radius", 0.7},
         {"material", principled(0.8, 0.25, 0.1, 0.3)}}};
    const test::Comparison c = test::compare_gpu_with_reference(shadowed_sky_scene(camera, objects, "foot.json"));
    std::cout << "sky at the foot of four objects: " << c.describe() << "\n";
    SCOPED_TRACE(c.describe());
    EXPECT_EQ(c.nonfinite_values, 0);
    EXPECT_LE(c.max_level_diff, kMaxLevelDiff);
    EXPECT_LE(c.max_abs_diff, 0.02);
    EXPECT_LE(std::abs(c.mean_signed_diff), 3e-5);
    EXPECT_LE(c.mean_abs_diff, 1e-3);
}

// A glossy principled floor and sphere under the unshadowed sky (roughness 0 and 0.1: GGX
// lobes of alpha 0.001 and 0.01, Phong exponents ~5e5 and ~5e3). A GGX lobe falls off as
// 1 / theta^4 beside its peak, a Phong lobe as exp(-e theta^2 / 2): drawn from the Phong
// lobe, the GGX tails were left to the sky's cosine-weighted samples, white fireflies (all
// pixels: max |diff| 3.4 and 0.49, mean 0.019 and 0.0081, 64.7 and 79.3 % on the same level).
// Now the sky's sharp lobes are drawn as GGX lobes (glsl/common/area_lights.glsl:
// lobe_technique_direction). Measured (interior pixels): max 0.0098 and 0.016, mean 6.0e-4
// and 7.0e-4, 98.0 and 97.8 %, 1 level at most. Roughness 1 has no lobe to draw from (e =
// 0.5 < 1) and takes the doubled side: its retro-reflection's noise with 8 x 8 samples was
// 94.0 % on the same level (all pixels, mean 1.8e-3); measured 98.3 %, 5.3e-4.
TEST(SkyOnTheGpu, APrincipledFloorOfAnyRoughnessConverges) {
    if (test::kSanitized) GTEST_SKIP() << kShaderNumericsOnly;
    const nlohmann::json camera = {{"projection", "perspective"}, {"position", {0, 2.4, 7.5}}, {"target", {0, 0.55, 0}},
                                   {"up", {0, 1, 0}}, {"fov_y_deg", 32}};
    for (const double roughness : {0.0, 0.1, 1.0}) {
        const nlohmann::json glossy = {{"model", "principled"}, {"base_color", {0.5, 0.5, 0.5}}, {"roughness", roughness}};
        const nlohmann::json objects = {
            {{"shape", "plane"}, {"center", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"size", 14}, {"material", glossy}},
            {{"shape", "sphere"}, {"center", {0, 0.7, 0}}, {"radius", 0.7}, {"material", glossy}}};
        const nlohmann::json sky = {{"type", "sky"}, {"intensity", 1.0}};
        const test::Comparison c = test::compare_gpu_with_reference(sky_scene(camera, objects, sky, "glossy.json"));
        std::cout << "sky on a principled floor, roughness " << roughness << ": " << c.describe() << "\n";
        SCOPED_TRACE(c.describe());
        EXPECT_EQ(c.nonfinite_values, 0);
        EXPECT_LE(c.max_level_diff, kMaxLevelDiff);
        EXPECT_LE(c.max_abs_diff, 0.03);
        EXPECT_LE(std::abs(c.mean_signed_diff), kBias);
        EXPECT_LE(c.mean_abs_diff, 1.5e-3);
        EXPECT_GE(c.same_level_share, 0.97);
    }
}

// A shadowed directional light with no area light in the scene (the programs
// then have shadows and no emitters): every family draws it, and the shadow
// only takes light away, from some pixels and never adds any.
TEST(HardShadowsAlone, CompileForEveryFamilyAndOnlyTakeLightAway) {
    const LightCase key{"directional", {{"type", "directional"}, {"direction", {1, 1.2, 0.8}}, {"intensity", 0.9}}};
    Renderer& renderer = test::shared_renderer();
    for (const MaterialCase& material : kMaterials) {
        SCOPED_TRACE(material.name);
        renderer.render(lit_scene(key, material, false));
        const std::vector<float> lit = renderer.read_raw().pixels;
        ASSERT_NO_THROW(renderer.render(lit_scene(key, material, true)));
        const std::vector<float> shadowed = renderer.read_raw().pixels;
        ASSERT_EQ(shadowed.size(), lit.size());
        long darker = 0, brighter = 0;
        for (std::size_t i = 0; i < lit.size(); ++i) {
            darker += shadowed[i] < lit[i];
            brighter += shadowed[i] > lit[i];
        }
        EXPECT_GT(darker, 300);
        EXPECT_EQ(brighter, 0);
    }
}

// A directional, point or spot light's shadow with no area light in the scene:
// one ray a pixel, a hard shadow (the programs take shadows without the area
// lights' sampling code).
TEST(HardShadowOnTheGpu, MatchesTheReferenceWithoutAreaLights) {
    const nlohmann::json lights[] = {
        {{"type", "directional"}, {"direction", {0.5, 0.7, 0.4}}, {"intensity", 1.0}},
        {{"type", "point"}, {"position", {1.5, 2.5, 1.5}}, {"intensity", 6.0}},
        {{"type", "spot"}, {"position", {-1.0, 3.0, 1.5}}, {"spot_direction", {0.3, -1.0, -0.4}}, {"spot_exponent", 4},
         {"intensity", 6.0}},
    };
    for (const nlohmann::json& light : lights) {
        const Scene scene = lit_scene({light["type"], light}, kMaterials[0], true);
        const test::Comparison c = test::compare_gpu_with_reference(scene);
        std::cout << light["type"].get<std::string>() << " shadow: " << c.describe() << "\n";
        SCOPED_TRACE(light["type"].get<std::string>() + ": " + c.describe());
        EXPECT_EQ(c.nonfinite_values, 0);
        EXPECT_LE(c.max_level_diff, kMaxLevelDiff);
        EXPECT_LE(std::abs(c.mean_signed_diff), kBias);
        EXPECT_GE(c.same_level_share, kSameLevelShare);
    }
}

// The explorer's preview (kFastSampling: n = 1, a hard shadow from one point)
// takes two points of an emitter for the paper's highlight and Phong, where
// the highlight is and the emitter's far side from it, weighed by the pair's
// two closed forms (glsl/common/lights.glsl): their cosine and (R.V)^m are in
// the pair's span, so the preview is exact for them unshadowed (to float:
// the reference's own error); every other family keeps one point.
class PreviewSampling {
public:
    explicit PreviewSampling(AreaSampling sampling) : saved_(test::shared_renderer().area_sampling()) {
        test::shared_renderer().set_area_sampling(sampling);
    }
    ~PreviewSampling() { test::shared_renderer().set_area_sampling(saved_); }
    PreviewSampling(const PreviewSampling&) = delete;
    PreviewSampling& operator=(const PreviewSampling&) = delete;

private:
    AreaSampling saved_;
};

TEST(PreviewOnTheGpu, TwoPointsMakeAHighlightExactAndLeaveOtherLobesToOnePoint) {
    for (int l = 0; l < 3; ++l)
        for (int m = 0; m < 5; ++m) {
            const Scene scene = lit_scene(kLights[l], kMaterials[m], false);
            const ref::ReferenceImage reference = ref::render_reference(scene);
            test::Comparison two, one;
            {
                const PreviewSampling preview(kFastSampling);
                two = test::compare_gpu_with(scene, reference);
            }
            {
                const PreviewSampling preview({1, 1, false});
                one = test::compare_gpu_with(scene, reference);
            }
            const std::string name = kLights[l].name + "_" + kMaterials[m].name;
            std::cout << name << " preview: " << two.describe() << "\n  one point: " << one.describe() << "\n";
            SCOPED_TRACE(name + ": " + two.describe() + "; one point: " + one.describe());
            EXPECT_EQ(two.nonfinite_values, 0);
            if (kMaterials[m].name != "highlight" && kMaterials[m].name != "phong") {
                EXPECT_EQ(two.mean_abs_diff, one.mean_abs_diff);
                EXPECT_EQ(two.max_abs_diff, one.max_abs_diff);
            } else {
                // Measured: max |diff| 1.5e-6-2.1e-5 (one point: 0.038-0.31, up to 9 levels off).
                EXPECT_LE(two.max_abs_diff, 1e-4);
                EXPECT_LE(two.max_level_diff, 1);  // a value on a level's edge
                EXPECT_GE(two.same_level_share, 0.999);
            }
        }
}

std::string param_name(const ::testing::TestParamInfo<Case>& info) { return case_name(info.param); }

// Family outermost, then light, then shadow: every fifth case (the sanitizer tree's part) then still
// holds every family, every light and both shadow settings, and the slow shadowed sky cases fall
// into different shards.
std::vector<Case> every_case() {
    std::vector<Case> cases;
    for (int m = 0; m < 5; ++m)
        for (int l = 0; l < 3; ++l)
            for (bool shadow : {false, true}) cases.emplace_back(l, m, shadow);
    return cases;
}

INSTANTIATE_TEST_SUITE_P(EveryLightEveryFamily, AreaLightOnTheGpu, ::testing::ValuesIn(every_case()), param_name);

}  // namespace
}  // namespace m3055
