// The Material section's disabled fields (explore/material_fields.h): a
// colour a conductor or a color_spectrum stands in for has no effect, and says why.
#include "explore/material_fields.h"
#include "models/model_table.h"
#include "scene/conductor_use.h"
#include "scene/load.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace m3055::explore {
namespace {

std::string reason(const Material& m, const char* name) { return inert_reason(m, m.model().param(name)); }

TEST(MaterialFields, APaperMetalsColourIsDisabledWhileAConductorIsPicked) {
    for (const char* model : {"metal", "metal_blinn", "metal_phong"}) {
        Material m = Material::of(model);
        EXPECT_EQ(reason(m, "color"), "") << model << ": conductor none, the colour is C0";
        m.set_choice("conductor", "gold");
        EXPECT_EQ(reason(m, "color"), "no effect: the conductor gold gives the colour per light")
            << model;
        EXPECT_NE(inert_detail(m, m.model().param("color")).find("Choose conductor none to use this colour C0 again."),
                  std::string::npos)
            << inert_detail(m, m.model().param("color"));
        for (const char* other : {"d", "lobes", "conductor", "fresnel"}) EXPECT_EQ(reason(m, other), "") << model << " " << other;
        m.set_choice("conductor", "none");
        EXPECT_EQ(reason(m, "color"), "") << model;
    }
}

TEST(MaterialFields, MicrofacetsKsIsDisabledUnderAConductorAndKdIsNot) {
    Material m = Material::of("microfacet");
    m.set_choice("conductor", "copper");
    EXPECT_EQ(reason(m, "ks"), "no effect: the conductor copper gives the colour per light");
    EXPECT_EQ(reason(m, "kd"), "") << "kd stays (docs/spec.md#72-measured-metals)";
}

// Turning a conductor off keeps the material's look: the colour it stood in
// for takes the metal's colour under D65 (not the red left under gold).
TEST(MaterialFields, AConductorTurnedOffLeavesItsD65ColourInTheColourItReplaced) {
    for (const auto& [model, colour] : {std::pair{"metal", "color"}, std::pair{"microfacet", "ks"}}) {
        Material m = Material::of(model);
        m.set_choice("conductor", "gold");
        const Material before = m;
        m.set_choice("conductor", "none");
        carry_replaced_colour(before, m, m.model().param("conductor"));
        const dvec3 gold = conductor_d65_colour("gold");
        EXPECT_GT(gold.r, 1.0) << "gold's D65 red passes 1: the field keeps its range";
        EXPECT_EQ(m.vec3(colour), dvec3(1.0, gold.g, gold.b)) << model;
        EXPECT_GT(gold.g, gold.b) << "gold is yellow: R > G > B";
        EXPECT_GT(gold.b, 0.2);
        Scene scene;
        scene.objects.push_back(Object{});
        scene.objects[0].material = m;
        EXPECT_NO_THROW(
            scene_from_json(scene_to_json(scene, PathWriting::absolute()), "saved.json", LoadContext::trusted()))
            << model << ": the scene saves and loads";
    }
}

TEST(MaterialFields, OtherChoicesLeaveTheColourAlone) {
    Material m = Material::of("metal");
    const dvec3 colour = m.vec3("color");
    m.set_choice("conductor", "gold");
    Material before = m;
    m.set_choice("conductor", "silver");  // another metal: the colour stays hidden, untouched
    carry_replaced_colour(before, m, m.model().param("conductor"));
    EXPECT_EQ(m.vec3("color"), colour);
    before = m;
    m.set_choice("fresnel", "full");
    carry_replaced_colour(before, m, m.model().param("fresnel"));
    EXPECT_EQ(m.vec3("color"), colour);
    Material plain = Material::of("metal");
    before = plain;
    plain.set_choice("conductor", "none");  // none to none: nothing was replaced
    carry_replaced_colour(before, plain, plain.model().param("conductor"));
    EXPECT_EQ(plain.vec3("color"), colour);
}

TEST(MaterialFields, AColourGivenAsASpectrumIsDisabledWithItsD65ColourShown) {
    Material m = Material::of("highlight");
    ReflectanceSpectrum spectrum;
    spectrum.nm = {400.0, 700.0};
    spectrum.values = {0.2, 0.8};
    m.set_colour_spectrum(&spectrum);
    EXPECT_EQ(reason(m, "color"), "no effect: the color_spectrum gives the colour per light");
    EXPECT_NE(inert_detail(m, m.model().param("color")).find("the spectrum's colour under D65"), std::string::npos);
    EXPECT_EQ(reason(m, "d"), "");
    m.set_colour_spectrum(nullptr);
    EXPECT_EQ(reason(m, "color"), "");
}

TEST(MaterialFields, AClassicModelsKdGivenAsASpectrumIsDisabled) {
    Material m = Material::of("phong");
    ReflectanceSpectrum spectrum;
    spectrum.nm = {400.0, 700.0};
    spectrum.values = {0.2, 0.8};
    m.set_colour_spectrum(&spectrum);
    EXPECT_EQ(reason(m, "kd"), "no effect: the kd_spectrum gives the colour per light");
    EXPECT_EQ(reason(m, "ka"), "") << "K_amb stays an RGB colour (its default: kd's D65 colour)";
    EXPECT_EQ(reason(m, "ks"), "");
}

TEST(MaterialFields, NoParameterOfAnyModelIsDisabledAtItsDefaults) {
    for (const ModelSpec& spec : model_table().models()) {
        const ModelSpec* model = &spec;
        const Material m(*model);
        for (const ParamSpec& param : model->params) {
            EXPECT_EQ(inert_reason(m, param), "") << model->name << " " << param.name;
            EXPECT_EQ(inert_detail(m, param), "") << model->name << " " << param.name;
        }
    }
}

}  // namespace
}  // namespace m3055::explore
