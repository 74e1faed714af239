// Scene files for the classic models (docs/spec.md#5-classic-models, docs/models.md): every model and
// parameter read exactly, defaults, one-line errors naming file and JSON path,
// the lecture's ambient fields, and the exact scene_to_json round trip.
#include "material_support.h"
#include "models/model_spec.h"
#include "reference/classic.h"
#include "scene/load.h"

#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

namespace m3055 {
namespace {

using nlohmann::json;

json base_scene(json material) {
    return {{"camera", {{"projection", "perspective"}, {"position", {0, 0, 4.5}}, {"target", {0, 0, 0}}, {"fov_y_deg", 30}}},
            {"lights", json::array({{{"type", "directional"}, {"direction", {1, 1, 1}}}})},
            {"objects", json::array({{{"shape", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}, {"material", material}}})}};
}

Material load_material(const json& material) {
    return scene_from_json(base_scene(material), "scene.json", LoadContext::trusted()).objects.at(0).material;
}

std::string error_of(const json& doc) {
    try {
        scene_from_json(doc, "scene.json", LoadContext::trusted());
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(no error)";
}

std::string material_error(const json& material) { return error_of(base_scene(material)); }

void expect_vec(const dvec3& a, const dvec3& b) {
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.y, b.y);
    EXPECT_EQ(a.z, b.z);
}

TEST(ClassicScene, EveryModelNameLoads) {
    const std::vector<std::string> names = test::builtin_models_of(Family::classic);
    ASSERT_GE(names.size(), 12u);  // lambert ... heidrich_seidel, minnaert, principled
    for (const std::string& name : names) {
        // The diffuse colour: kd, or principled's base_color; ka defaults to it (seed 001).
        const std::string colour = Material::of(name).model().param("ka").default_from;
        ASSERT_TRUE(colour == "kd" || colour == "base_color") << name;
        const Material m = load_material({{"model", name}, {colour, {0.5, 0.25, 0.125}}});
        EXPECT_EQ(m.model_name(), name);
        EXPECT_EQ(m.model().family, Family::classic);
        expect_vec(m.vec3(colour), {0.5, 0.25, 0.125});
        expect_vec(m.vec3("ka"), {0.5, 0.25, 0.125});
        expect_vec(m.vec3("emission"), {0, 0, 0});
    }
}

TEST(ClassicScene, ParametersAreReadExactly) {
    const Material phong = load_material({{"model", "phong"}, {"kd", {0.1, 0.2, 0.3}}, {"ka", {0.3, 0.2, 0.1}},
                                          {"ks", {0.9, 0.8, 0.7}}, {"emission", {0.01, 0.02, 0.03}},
                                          {"shininess", 42.5}});
    expect_vec(phong.vec3("ka"), {0.3, 0.2, 0.1});
    expect_vec(phong.vec3("ks"), {0.9, 0.8, 0.7});
    expect_vec(phong.vec3("emission"), {0.01, 0.02, 0.03});
    EXPECT_EQ(phong.number("shininess"), 42.5);

    const Material on = load_material({{"model", "oren_nayar"}, {"kd", {1, 1, 1}}, {"sigma", 0.35}});
    EXPECT_EQ(on.number("sigma"), 0.35);

    const Material mf = load_material({{"model", "microfacet"}, {"kd", {0, 0, 0}}, {"distribution", "ggx"},
                                       {"fresnel", "dielectric"}, {"ior", 1.33},
                                       {"lobes", {{{"w", 0.7}, {"m", 0.1}}, {{"w", 0.3}, {"m", 0.6}}}}});
    EXPECT_EQ(static_cast<ref::Distribution>(mf.choice("distribution")), ref::Distribution::ggx);
    EXPECT_EQ(static_cast<ref::Fresnel>(mf.choice("fresnel")), ref::Fresnel::dielectric);
    EXPECT_EQ(mf.number("ior"), 1.33);
    ASSERT_EQ(mf.lobes().size(), 2u);
    EXPECT_EQ(mf.lobes()[1].w, 0.3);
    EXPECT_EQ(mf.lobes()[1].m, 0.6);

    const Material bp = load_material({{"model", "microfacet"}, {"kd", {0, 0, 0}}, {"distribution", "blinn_phong"},
                                       {"lobes", {{{"w", 1}, {"n", 250}}}}});
    ASSERT_FALSE(bp.lobes().empty());
    EXPECT_EQ(bp.lobes()[0].m, 250.0);

    const Material ward = load_material({{"model", "ward"}, {"kd", {0, 0, 0}}, {"alpha_x", 0.05}, {"alpha_y", 0.4},
                                         {"axis", {0, 0, 2}}});
    EXPECT_EQ(ward.number("alpha_x"), 0.05);
    EXPECT_EQ(ward.number("alpha_y"), 0.4);
    expect_vec(ward.vec3("axis"), {0, 0, 1});  // normalized on load
}

TEST(ClassicScene, Defaults) {
    const Material mf = load_material({{"model", "microfacet"}, {"kd", {0, 0, 0}}});
    EXPECT_EQ(static_cast<ref::Distribution>(mf.choice("distribution")), ref::Distribution::beckmann);
    EXPECT_EQ(static_cast<ref::Fresnel>(mf.choice("fresnel")), ref::Fresnel::schlick);
    EXPECT_EQ(mf.number("ior"), 1.5);
    ASSERT_EQ(mf.lobes().size(), 1u);
    EXPECT_EQ(mf.lobes()[0].m, 0.3);
    expect_vec(mf.vec3("ks"), {1, 1, 1});
    const Material bp = load_material({{"model", "microfacet"}, {"kd", {0, 0, 0}}, {"distribution", "blinn_phong"}});
    ASSERT_FALSE(bp.lobes().empty());
    EXPECT_EQ(bp.lobes()[0].m, 100.0);
    const Material hs = load_material({{"model", "heidrich_seidel"}, {"kd", {0, 0, 0}}});
    EXPECT_EQ(hs.number("shininess"), 32.0);
    expect_vec(hs.vec3("axis"), {0, 1, 0});
}

// disney.brdf's parameter block: every number in [0, 1], its defaults; the base
// colour its default baseColor (.82, .67, .16) through mon2lin (x^2.2): ours is linear.
TEST(ClassicScene, PrincipledTakesDisneyBrdfsRangesAndDefaults) {
    const Material m = load_material({{"model", "principled"}});
    expect_vec(m.vec3("base_color"), {std::pow(0.82, 2.2), std::pow(0.67, 2.2), std::pow(0.16, 2.2)});
    expect_vec(m.vec3("ka"), m.vec3("base_color"));
    expect_vec(m.vec3("emission"), {0, 0, 0});
    const std::pair<const char*, double> defaults[] = {
        {"subsurface", 0.0}, {"metallic", 0.0},  {"specular", 0.5}, {"specular_tint", 0.0},
        {"roughness", 0.5},  {"anisotropic", 0.0}, {"sheen", 0.0},  {"sheen_tint", 0.5},
        {"clearcoat", 0.0},  {"clearcoat_gloss", 1.0}};
    for (const auto& [name, value] : defaults) {
        EXPECT_EQ(m.number(name), value) << name;
        const ParamSpec& spec = m.model().param(name);
        EXPECT_EQ(spec.range.lo, 0.0) << name;
        EXPECT_EQ(spec.range.hi, 1.0) << name;
    }
    expect_vec(m.vec3("axis"), {0, 1, 0});
    const Material given = load_material({{"model", "principled"}, {"base_color", {0.2, 0.4, 0.6}}});
    expect_vec(given.vec3("ka"), {0.2, 0.4, 0.6});  // the ambient colour follows the base colour
    const std::string at = "scene.json: objects[0].material.";
    EXPECT_EQ(material_error({{"model", "principled"}, {"kd", {1, 1, 1}}}),
              at + "kd: not a parameter of model principled (its base colour is \"base_color\")");
    EXPECT_EQ(material_error({{"model", "principled"}, {"color", {1, 1, 1}}}),
              at + "color: not a parameter of model principled (its base colour is \"base_color\")");
    EXPECT_EQ(material_error({{"model", "principled"}, {"roughness", 1.5}}), at + "roughness: must be in [0, 1], got 1.5");
    EXPECT_EQ(material_error({{"model", "principled"}, {"ks", {1, 1, 1}}}), at + "ks: not a parameter of model principled");
}

TEST(ClassicScene, LectureAmbientFields) {
    json doc = base_scene({{"model", "lambert"}, {"kd", {1, 1, 1}}});
    doc["ambient"] = {0.1, 0.2, 0.3};
    doc["lights"][0]["ambient"] = {0.4, 0.5, 0.6};
    const Scene scene = scene_from_json(doc, "scene.json", LoadContext::trusted());
    expect_vec(scene.ambient, {0.1, 0.2, 0.3});
    expect_vec(scene.lights[0].ambient, {0.4, 0.5, 0.6});
    const Scene plain =
        scene_from_json(base_scene({{"model", "lambert"}, {"kd", {1, 1, 1}}}), "scene.json", LoadContext::trusted());
    expect_vec(plain.ambient, {0, 0, 0});
    expect_vec(plain.lights[0].ambient, {0, 0, 0});
}

TEST(ClassicScene, ErrorsNameTheFileAndThePath) {
    const std::string m = "scene.json: objects[0].material.";
    EXPECT_EQ(material_error({{"model", "lambert"}}), m + "kd: is required");
    EXPECT_EQ(material_error({{"model", "lambert"}, {"kd", {1, 1, 1}}, {"color", {1, 1, 1}}}),
              m + "color: not a parameter of model lambert (its diffuse colour is \"kd\")");
    EXPECT_EQ(material_error({{"model", "lambert"}, {"kd", {1, 1, 1}}, {"ks", {1, 1, 1}}}),
              m + "ks: not a parameter of model lambert");
    EXPECT_EQ(material_error({{"model", "phong"}, {"kd", {1, 1, 1}}, {"sigma", 0.3}}),
              m + "sigma: not a parameter of model phong");
    EXPECT_EQ(material_error({{"model", "highlight"}, {"color", {1, 1, 1}}, {"kd", {1, 1, 1}}}),
              m + "kd: not a parameter of model highlight");
    EXPECT_EQ(material_error({{"model", "lambert"}, {"kd", {1, 1.5, 1}}}), m + "kd[1]: must be in [0, 1], got 1.5");
    EXPECT_EQ(material_error({{"model", "phong"}, {"kd", {1, 1, 1}}, {"shininess", -1}}),
              m + "shininess: must be in [0, 10000], got -1");
    EXPECT_EQ(material_error({{"model", "oren_nayar"}, {"kd", {1, 1, 1}}, {"sigma", 11}}),
              m + "sigma: must be in [0, 10], got 11");
    EXPECT_EQ(material_error({{"model", "microfacet"}, {"kd", {1, 1, 1}}, {"distribution", "cauchy"}}),
              m + "distribution: must be \"blinn_phong\", \"gaussian\", \"beckmann\" or \"ggx\", got \"cauchy\"");
    EXPECT_EQ(material_error({{"model", "microfacet"}, {"kd", {1, 1, 1}}, {"fresnel", 1}}),
              m + "fresnel: must be \"none\", \"schlick\" or \"dielectric\", got 1");
    EXPECT_EQ(material_error({{"model", "microfacet"}, {"kd", {1, 1, 1}}, {"ior", 0.9}}),
              m + "ior: must be in [1, 5], got 0.9");
    EXPECT_EQ(material_error({{"model", "microfacet"}, {"kd", {1, 1, 1}}, {"lobes", {{{"w", 1}, {"m", 0}}}}}),
              m + "lobes[0].m: must be in [0.001, 2], got 0");
    EXPECT_EQ(material_error({{"model", "microfacet"}, {"kd", {1, 1, 1}}, {"lobes", {{{"w", 1.5}, {"m", 0.2}}}}}),
              m + "lobes[0].w: must be in [0, 1], got 1.5");
    EXPECT_EQ(material_error({{"model", "microfacet"}, {"kd", {1, 1, 1}}, {"distribution", "blinn_phong"},
                              {"lobes", {{{"w", 1}, {"m", 0.2}}}}}),
              m + "lobes[0].m: not a parameter of distribution blinn_phong (its lobes use \"w\" and \"n\")");
    EXPECT_EQ(material_error({{"model", "microfacet"}, {"kd", {1, 1, 1}}, {"lobes", json::array()}}),
              m + "lobes: must have 1 to 4 lobes, got 0");
    EXPECT_EQ(material_error({{"model", "ward"}, {"kd", {1, 1, 1}}, {"alpha_y", 0}}),
              m + "alpha_y: must be in [0.001, 1], got 0");
    EXPECT_EQ(material_error({{"model", "ward"}, {"kd", {1, 1, 1}}, {"axis", {0, 0, 0}}}), m + "axis: must be non-zero");
    json doc = base_scene({{"model", "lambert"}, {"kd", {1, 1, 1}}});
    doc["ambient"] = {0, 0, 2};
    EXPECT_EQ(error_of(doc), "scene.json: ambient[2]: must be in [0, 1], got 2");
    doc = base_scene({{"model", "lambert"}, {"kd", {1, 1, 1}}});
    doc["lights"][0]["ambient"] = "dim";
    EXPECT_EQ(error_of(doc), "scene.json: lights[0].ambient: must be an array of 3 numbers");
}

TEST(ClassicScene, RoundTripIsExact) {
    json doc = base_scene({{"model", "microfacet"}, {"kd", {0.1, 0.2, 0.30000000000000004}}, {"ka", {0.7, 0.1, 0.2}},
                           {"ks", {0.9, 0.9, 0.9}}, {"emission", {0.01, 0, 0}}, {"distribution", "gaussian"},
                           {"fresnel", "none"}, {"ior", 2.4}, {"lobes", {{{"w", 0.25}, {"m", 0.123456789}}}}});
    doc["ambient"] = {0.05, 0.05, 0.1};
    doc["lights"][0]["ambient"] = {0.2, 0.1, 0.0};
    json more = doc["objects"][0];
    const json others[] = {
        {{"model", "ward"}, {"kd", {0, 0, 0}}, {"alpha_x", 0.011}, {"alpha_y", 0.7}, {"axis", {1, 2, 3}}},
        {{"model", "heidrich_seidel"}, {"kd", {0, 0, 0}}, {"shininess", 7.25}, {"axis", {0, 0, 1}}},
        {{"model", "oren_nayar"}, {"kd", {0.5, 0.5, 0.5}}, {"sigma", 0.3}},
        {{"model", "half_lambert_clamped"}, {"kd", {0.5, 0.5, 0.5}}},
        {{"model", "blinn_phong"}, {"kd", {0.5, 0.5, 0.5}}, {"shininess", 1e4}},
        {{"model", "microfacet"}, {"kd", {0, 0, 0}}, {"distribution", "blinn_phong"}, {"lobes", {{{"w", 1}, {"n", 3}}}}},
        {{"model", "principled"}, {"base_color", {0.1, 0.7, 0.30000000000000004}}, {"subsurface", 0.25},
         {"metallic", 0.125}, {"specular", 0.75}, {"specular_tint", 0.3}, {"roughness", 0.123456789},
         {"anisotropic", 0.9}, {"sheen", 1}, {"sheen_tint", 0}, {"clearcoat", 0.6}, {"clearcoat_gloss", 0.05},
         {"axis", {1, 0, 0}}, {"emission", {0, 0.01, 0}}},
        {{"model", "principled"}},
    };
    for (const json& material : others) {
        more["material"] = material;
        doc["objects"].push_back(more);
    }
    const Scene a = scene_from_json(doc, "scene.json", LoadContext::trusted());
    const Scene b =
        scene_from_json(scene_to_json(a, PathWriting::absolute()), "roundtrip.json", LoadContext::trusted());
    expect_vec(b.ambient, a.ambient);
    expect_vec(b.lights[0].ambient, a.lights[0].ambient);
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (std::size_t i = 0; i < a.objects.size(); ++i) {
        const Material& x = a.objects[i].material;
        const Material& y = b.objects[i].material;
        SCOPED_TRACE(x.model_name());
        EXPECT_TRUE(test::same_material(x, y));  // the model and every parameter, exactly
    }
    // Scenes without the lecture's ambient write no "ambient" key (old files unchanged).
    const json plain = scene_to_json(
        scene_from_json(base_scene({{"model", "lambert"}, {"kd", {1, 1, 1}}}), "s.json", LoadContext::trusted()),
        PathWriting::absolute());
    EXPECT_FALSE(plain.contains("ambient"));
    EXPECT_FALSE(plain["lights"][0].contains("ambient"));
}

}  // namespace
}  // namespace m3055
