// The model table (renderer/models/): every entry is complete and consistent,
// and what is derived from it holds for every model and every parameter: the
// GLSL and reference hooks exist, the loader accepts each parameter at the
// ends of its range and rejects it just outside, scene_to_json round-trips
// it, the GPU record carries it, and run-time models are checked like
// built-in ones.
#include "gl/shader_source.h"
#include "reference/hooks.h"
#include "models/glsl_generator.h"
#include "models/model_table.h"
#include "passes/material_buffer.h"
#include "reference/classic.h"
#include "scene/load.h"
#include "gpu_compare.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <regex>

namespace m3055 {
namespace {

using nlohmann::json;

// A GLSL function definition "TYPE NAME(" in `text`.
bool defines_function(const std::string& text, const std::string& name) {
    return std::regex_search(text, std::regex("(^|\\n)\\s*(vec3|float|void|int)\\s+" + name + "\\s*\\("));
}

// The GLSL a program with every model sees (the models' files included).
std::string all_model_glsl() {
    return compose_shader("models/shade.glsl", every_model_define(model_table())).text;
}

TEST(ModelTable, EveryEntryHasItsHooksInGlslAndInTheReference) {
    const std::string glsl = all_model_glsl();
    for (const ModelSpec& model : model_table().models()) {
        SCOPED_TRACE(model.name);
        EXPECT_FALSE(model.label.empty());
        EXPECT_FALSE(model.citation.empty());
        EXPECT_FALSE(model.summary.empty());
        EXPECT_NE(find_glsl_source(model.glsl_file), nullptr) << model.glsl_file;
        EXPECT_TRUE(defines_function(glsl, model.glsl_hook)) << model.glsl_hook;
        if (!model.glsl_specular.empty()) {
            EXPECT_TRUE(defines_function(glsl, model.glsl_specular)) << model.glsl_specular;
        }
        const ref::ReferenceHooks& r = ref::reference_hooks(model);
        EXPECT_TRUE(ref::has_reference(model));
        switch (model.family) {
            case Family::opaque: EXPECT_NE(r.opaque, nullptr); break;
            case Family::translucent: EXPECT_NE(r.translucent, nullptr); break;
            case Family::metal: EXPECT_NE(r.metal, nullptr); break;
            case Family::classic:
                EXPECT_NE(r.classic_diffuse, nullptr);
                EXPECT_EQ(r.classic_specular != nullptr, !model.glsl_specular.empty());
                break;
        }
    }
}

TEST(ModelTable, EveryParameterHasHelpAndALabel) {
    for (const ModelSpec& model : model_table().models())
        for (const ParamSpec& param : model.params) {
            EXPECT_FALSE(param.label.empty()) << model.name << "." << param.name;
            EXPECT_FALSE(param.help.empty()) << model.name << "." << param.name;
            EXPECT_FALSE(param.cite.empty()) << model.name << "." << param.name;
        }
}

// The explorer shows a choice by its label where the table gives one: the
// measured metals' F switch reads as the spec names its two ways.
TEST(ModelTable, ChoiceLabelsNameEveryChoiceAndTheFSwitchReadsAsTheSpec) {
    for (const ModelSpec& model : model_table().models())
        for (const ParamSpec& param : model.params)
            if (!param.choice_labels.empty())
                EXPECT_EQ(param.choice_labels.size(), param.choices.size()) << model.name << "." << param.name;
    const ParamSpec& f = model_table().find("metal")->param("fresnel");
    ASSERT_EQ(f.choice_labels.size(), 2u);
    EXPECT_EQ(f.choice_labels[0].rfind("F(\u03bb, 0)", 0), 0u) << f.choice_labels[0];
    EXPECT_NE(f.choice_labels[1].find("eq. 19"), std::string::npos) << f.choice_labels[1];
}

TEST(ModelTable, ParametersOfTheSameNameAgreeAcrossModels) {
    // One GLSL field, one range and one set of choices per name: a value carried
    // from one model to another (with_model) stays valid.
    std::map<std::string, const ParamSpec*> first;
    for (const ModelSpec& model : model_table().models())
        for (const ParamSpec& param : model.params) {
            const auto [it, added] = first.emplace(param.name, &param);
            if (added) continue;
            EXPECT_EQ(it->second->kind, param.kind) << model.name << "." << param.name;
            EXPECT_EQ(it->second->range.lo, param.range.lo) << model.name << "." << param.name;
            EXPECT_EQ(it->second->range.hi, param.range.hi) << model.name << "." << param.name;
            // Choices: the same list, or lists with no choice in common (the
            // metals' fresnel normal/full, microfacet's none/schlick/dielectric:
            // with_model carries neither, and their GLSL constants differ).
            if (it->second->choices == param.choices) continue;
            for (const std::string& choice : param.choices)
                EXPECT_EQ(std::count(it->second->choices.begin(), it->second->choices.end(), choice), 0)
                    << model.name << "." << param.name << ": " << choice;
        }
}

// ---- The loader, from the table -----------------------------------------------------

json scene_with(const json& material) {
    return {{"camera", {{"projection", "perspective"}, {"position", {0, 0, 4}}, {"target", {0, 0, 0}},
                        {"fov_y_deg", 30}}},
            {"objects", json::array({{{"center", {0, 0, 0}}, {"radius", 1}, {"material", material}}})}};
}

// The smallest valid material of `model`: its required parameters at their defaults.
json minimal_material(const ModelSpec& model) {
    json material = {{"model", model.name}};
    for (const ParamSpec& param : model.params)
        if (param.required) material[param.name] = param.fallback;
    return material;
}

// Loads `material` (in a scene); "" on success, else the loader's message.
std::string load_error(const json& material) {
    try {
        scene_from_json(scene_with(material), "t.json", LoadContext::trusted());
        return "";
    } catch (const SceneError& e) {
        return e.what();
    }
}

Material load(const json& material) {
    return scene_from_json(scene_with(material), "t.json", LoadContext::trusted()).objects[0].material;
}

double below(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }
double above(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }

TEST(ModelTable, LoaderAcceptsEveryNumberAtItsRangeEndsAndRejectsJustOutside) {
    for (const ModelSpec& model : model_table().models()) {
        for (const ParamSpec& param : model.params) {
            if (param.kind != ParamKind::number) continue;
            SCOPED_TRACE(model.name + "." + param.name);
            const std::string path = "objects[0].material." + param.name;
            for (double end : {param.range.lo, param.range.hi}) {
                json m = minimal_material(model);
                m[param.name] = end;
                ASSERT_EQ(load_error(m), "");
                EXPECT_EQ(load(m).number(param.name), end);
            }
            for (double outside : {below(param.range.lo), above(param.range.hi)}) {
                json m = minimal_material(model);
                m[param.name] = outside;
                const std::string error = load_error(m);
                EXPECT_NE(error.find("t.json: " + path + ": must be " + param.range.text()), std::string::npos)
                    << error;
            }
        }
    }
}

TEST(ModelTable, LoaderChecksColoursDirectionsAndChoicesOfEveryModel) {
    for (const ModelSpec& model : model_table().models()) {
        for (const ParamSpec& param : model.params) {
            SCOPED_TRACE(model.name + "." + param.name);
            json m = minimal_material(model);
            if (param.kind == ParamKind::colour) {
                m[param.name] = {0, 1, 0.5};
                EXPECT_EQ(load_error(m), "");
                m[param.name] = {0, above(1.0), 0.5};
                EXPECT_NE(load_error(m).find(param.name + "[1]: must be in [0, 1]"), std::string::npos);
                m[param.name] = {below(0.0), 1, 0.5};
                EXPECT_NE(load_error(m).find(param.name + "[0]: must be in [0, 1]"), std::string::npos);
            } else if (param.kind == ParamKind::direction) {
                m[param.name] = {0, 0, 3};
                EXPECT_EQ(load(m).vec3(param.name), dvec3(0, 0, 1));  // stored unit
                m[param.name] = {0, 0, 0};
                EXPECT_NE(load_error(m).find(param.name + ": must be non-zero"), std::string::npos);
            } else if (param.kind == ParamKind::choice) {
                for (std::size_t i = 0; i < param.choices.size(); ++i) {
                    m[param.name] = param.choices[i];
                    // A choice that stands in for another parameter ("conductor"
                    // for "color") is given without it, and with it is refused.
                    if (!param.replaces.empty() && i > 0) {
                        json with = m;
                        with[param.replaces] = model.param(param.replaces).fallback;
                        EXPECT_NE(load_error(with).find("gives both \"" + param.replaces + "\" and \"" +
                                                     param.name + "\""),
                                  std::string::npos);
                        json without = m;
                        without.erase(param.replaces);
                        EXPECT_EQ(load(without).choice(param.name), int(i));
                        continue;
                    }
                    EXPECT_EQ(load(m).choice(param.name), int(i));
                }
                m[param.name] = "no such choice";
                EXPECT_NE(load_error(m).find(param.name + ": must be \"" + param.choices[0] + "\""),
                          std::string::npos);
            }
        }
    }
}

TEST(ModelTable, LoaderChecksLobeListsAtTheirEnds) {
    for (const ModelSpec& model : model_table().models()) {
        const ParamSpec* param = model.find("lobes");
        if (!param) continue;
        const Material defaults(model);
        const LobeForm& form = param->form_for(defaults);
        SCOPED_TRACE(model.name);
        json m = minimal_material(model);
        json four = json::array();
        for (int j = 0; j < kMaxLobes; ++j)
            four.push_back({{"w", j % 2 ? form.weight.hi : form.weight.lo}, {form.key, j % 2 ? form.value.lo : form.value.hi}});
        m["lobes"] = four;
        ASSERT_EQ(load_error(m), "");
        EXPECT_EQ(load(m).lobes().count, kMaxLobes);
        four.push_back(four[0]);
        m["lobes"] = four;
        EXPECT_NE(load_error(m).find("lobes: must have 1 to 4 lobes"), std::string::npos);
        m["lobes"] = json::array({{{"w", above(form.weight.hi)}, {form.key, form.value.lo}}});
        EXPECT_NE(load_error(m).find("lobes[0].w: must be " + form.weight.text()), std::string::npos);
        m["lobes"] = json::array({{{"w", form.weight.lo}, {form.key, below(form.value.lo)}}});
        EXPECT_NE(load_error(m).find("lobes[0]." + form.key + ": must be " + form.value.text()), std::string::npos);
    }
}

TEST(ModelTable, DefaultsRoundTripAndReachTheGpuRecord) {
    for (const ModelSpec& model : model_table().models()) {
        SCOPED_TRACE(model.name);
        const Material defaults(model);
        // A file with only the required keys loads as the table's defaults.
        EXPECT_EQ(load(minimal_material(model)), defaults);
        Scene scene = scene_from_json(scene_with(minimal_material(model)), "t.json", LoadContext::trusted());
        EXPECT_EQ(scene_from_json(scene_to_json(scene, PathWriting::absolute()), "again.json", LoadContext::trusted())
                      .objects[0]
                      .material,
                  defaults);
        std::vector<float> record;
        pack_material(defaults, record);
        ASSERT_EQ(record.size(), std::size_t(material_record_texels()) * 4);
        EXPECT_EQ(record[0], float(model.id));
        EXPECT_EQ(record[1], float(static_cast<int>(model.family)));
        for (std::size_t i = 0; i < defaults.values().size(); ++i) EXPECT_EQ(record[2 + i], float(defaults.values()[i]));
    }
}

TEST(ModelTable, ChoicesOfTheMicrofacetModelNameTheReferenceTerms) {
    // The table's "distribution" choices index ref::Distribution: each name must
    // select the term of that name.
    const ParamSpec& d = model_table().get("microfacet").param("distribution");
    const double NoH = 0.9, theta_h = std::acos(NoH);
    const std::map<std::string, double> expected = {
        {"blinn_phong", ref::blinn_phong_D(20.0, NoH)},
        {"gaussian", -1.0},  // b from gaussian_norm: checked by its own tests
        {"beckmann", ref::beckmann_normalized_D(20.0, NoH)},
        {"ggx", ref::ggx_D(20.0, NoH)}};
    ASSERT_EQ(d.choices.size(), expected.size());
    for (std::size_t i = 0; i < d.choices.size(); ++i) {
        if (d.choices[i] == "gaussian") continue;
        EXPECT_EQ(ref::microfacet_D(static_cast<ref::Distribution>(i), 20.0, NoH, theta_h), expected.at(d.choices[i]))
            << d.choices[i];
    }
    const ParamSpec& f = model_table().get("microfacet").param("fresnel");
    EXPECT_EQ(f.choices, (std::vector<std::string>{"none", "schlick", "dielectric"}));  // ref::Fresnel's order
}

// ---- The GPU against the reference, for every entry -------------------------------------

// Every model of the table, at its defaults, under three coloured lights of
// each kind: the GLSL hook and the reference hook agree (the tolerances of
// tests/gpu_vs_reference_test.cpp), specialized and general. A model added to
// the table is covered without a new test.
TEST(ModelTable, EveryModelRendersOnTheGpuAsTheReferenceSays) {
    std::vector<Light> lights = {test::directional({1, 1, 1}, 1.0, {1.0, 0.9, 0.8}),
                                 test::directional({-1, -0.3, 0.8}, 0.5, {0.6, 0.7, 1.0})};
    Light point;
    point.type = LightType::point;
    point.position = {0.5, 2.0, 3.0};
    point.intensity = 4.0;
    point.att_quadratic = 0.5;
    lights.push_back(point);
    for (const ModelSpec& model : model_table().models()) {
        for (ShaderMode mode : {ShaderMode::specialized, ShaderMode::general}) {
            SCOPED_TRACE(model.name + (mode == ShaderMode::general ? " general" : " specialized"));
            const test::Comparison c =
                test::compare_gpu_with_reference(test::single_sphere_scene(Material(model), lights, false), mode);
            EXPECT_EQ(c.nonfinite_values, 0);
            EXPECT_GT(c.interior_pixels, 10000);
            EXPECT_LE(c.max_scaled_diff, 1e-3) << c.describe();
            EXPECT_GE(c.same_level_share, 0.999) << c.describe();
        }
    }
}

// ---- Model switching and run-time models ------------------------------------------------

TEST(ModelTable, SwitchingModelsKeepsValuesOfTheSameMeaning) {
    Material paper = Material::of("highlight");
    paper.set_vec3("color", {0.1, 0.2, 0.3});
    const Material classic = with_model(paper, model_table().get("phong"));
    EXPECT_EQ(classic.vec3("kd"), dvec3(0.1, 0.2, 0.3));  // C0 becomes K_diff and K_amb
    EXPECT_EQ(classic.vec3("ka"), dvec3(0.1, 0.2, 0.3));
    EXPECT_EQ(with_model(classic, model_table().get("metal")).vec3("color"), dvec3(0.1, 0.2, 0.3));

    Material blinn = Material::of("metal_blinn");
    blinn.set_lobes({{0.5, 7.0}});
    blinn.set_number("d", 0.3);
    const Material phong = with_model(blinn, model_table().get("metal_phong"));
    EXPECT_EQ(phong.lobes().to_vector()[0].m, 7.0);  // exponents on both: kept
    EXPECT_EQ(phong.number("d"), 0.3);
    const Material metal = with_model(blinn, model_table().get("metal"));
    EXPECT_EQ(metal.lobes().to_vector()[0].m, Material::of("metal").lobes()[0].m);  // n_j are not m_j
    // From another family, the metals' d is their own default (eq. 14 with their lobes).
    EXPECT_EQ(with_model(Material::of("highlight"), model_table().get("metal")).number("d"), 0.05);

    // principled: kd becomes the base colour; ka, emission and a ward's axis stay.
    Material ward = Material::of("ward");
    ward.set_vec3("kd", {0.1, 0.2, 0.3});
    ward.set_vec3("ka", {0.3, 0.2, 0.1});
    ward.set_vec3("emission", {0.01, 0.02, 0.03});
    ward.set_vec3("axis", {0.0, 0.0, 1.0});
    const Material principled = with_model(ward, model_table().get("principled"));
    EXPECT_EQ(principled.vec3("base_color"), dvec3(0.1, 0.2, 0.3));
    EXPECT_EQ(principled.vec3("ka"), dvec3(0.3, 0.2, 0.1));
    EXPECT_EQ(principled.vec3("emission"), dvec3(0.01, 0.02, 0.03));
    EXPECT_EQ(principled.vec3("axis"), dvec3(0.0, 0.0, 1.0));
    EXPECT_EQ(principled.number("roughness"), 0.5);  // its own default
    EXPECT_EQ(with_model(principled, model_table().get("lambert")).vec3("kd"), dvec3(0.1, 0.2, 0.3));
}

// A model switch keeps the object's colour between every
// two built-in models (C0 "color" of the paper's models, "kd" of the classic
// ones, principled's "base_color": carry_from in builtin_models.cpp), never the
// new model's default red.
TEST(ModelTable, EverySwitchBetweenBuiltInModelsKeepsTheColour) {
    auto colour_param = [](const ModelSpec& m) -> const char* {
        if (m.find("color")) return "color";
        if (m.find("kd")) return "kd";
        if (m.find("base_color")) return "base_color";
        return nullptr;
    };
    int pairs = 0;
    for (const ModelSpec& from : model_table().models()) {
        const char* from_colour = colour_param(from);
        if (!from_colour || from.id < 0) continue;
        Material blue(from);
        blue.set_vec3(from_colour, {0.1, 0.2, 0.9});
        for (const ModelSpec& to : model_table().models()) {
            const char* to_colour = colour_param(to);
            if (!to_colour || to.id < 0) continue;
            EXPECT_EQ(with_model(blue, to).vec3(to_colour), dvec3(0.1, 0.2, 0.9)) << from.name << " -> " << to.name;
            ++pairs;
        }
    }
    EXPECT_GT(pairs, 100);
}

TEST(ModelTable, RejectsInconsistentRunTimeModels) {
    ModelSpec good;
    good.name = "test_runtime_lambert_copy";
    good = model_table().get("lambert");
    good.name = "test_runtime_lambert_copy";
    good.id = -1;
    auto rejected = [](ModelSpec spec, const std::string& needle) {
        try {
            mutable_model_table().add(std::move(spec));
        } catch (const std::invalid_argument& e) {
            return std::string(e.what()).find(needle) != std::string::npos;
        }
        return false;
    };
    ModelSpec duplicate = good;
    duplicate.name = "lambert";
    EXPECT_TRUE(rejected(duplicate, "already in the table"));
    ModelSpec bad_name = good;
    bad_name.name = "Lambert Copy";
    EXPECT_TRUE(rejected(bad_name, "name must be"));
    ModelSpec out_of_range = good;
    out_of_range.params[0].fallback = {2.0, 0.0, 0.0};
    EXPECT_TRUE(rejected(out_of_range, "colour outside [0, 1]"));
    ModelSpec clash = good;
    clash.params.push_back(clash.params[0]);
    clash.params.back().name = "shininess";  // a number elsewhere, a colour here
    EXPECT_TRUE(rejected(clash, "\"shininess\" is a colour here but a number"));
    ModelSpec missing = good;
    missing.params.erase(missing.params.begin() + 2);  // emission: the classic family reads it
    EXPECT_TRUE(rejected(missing, "needs parameter \"emission\""));

    const std::uint64_t revision = model_table().revision();
    const ModelSpec& added = mutable_model_table().add(good);
    EXPECT_EQ(model_table().revision(), revision + 1);
    EXPECT_EQ(&model_table().get("test_runtime_lambert_copy"), &added);
    EXPECT_EQ(load(minimal_material(added)).model_name(), "test_runtime_lambert_copy");
}

}  // namespace
}  // namespace m3055
