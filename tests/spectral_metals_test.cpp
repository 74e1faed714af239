// Measured metals (docs/spec.md#72-measured-metals): the data files, eq. 19 with a
// complex index, the metals' colours against a separate derivation and a published
// table, energy, and the scene format's "conductor" / "fresnel".
#include "reference/classic.h"
#include "reference/conductor.h"
#include "scene/load.h"
#include "spectral/cie_data.h"
#include "spectral/colorimetry.h"
#include "spectral/conductor.h"
#include "spectral/reflected_colour.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

namespace m3055 {
namespace {

using nlohmann::json;

glm::dvec3 d65_normal_c0(const std::string& metal) {
    const spectral::ComplexIndex& index = spectral::conductor(metal);
    return spectral::reflected_c0(spectral::light_power(0.0, "D65"),
                                  [&](double nm) { return spectral::normal_reflectance(index.at(nm)); });
}

TEST(SpectralMetals, EveryDataFileParsesAndCoversTheObserver) {
    const std::vector<std::string> expected = {"aluminium", "chromium", "copper", "gold",
                                               "iron",      "nickel",   "silver", "titanium"};
    EXPECT_EQ(spectral::conductor_names(), expected);
    for (const std::string& name : expected) {
        const spectral::ComplexIndex& index = spectral::conductor(name);
        EXPECT_LE(index.nm.front(), 360.0) << name;
        EXPECT_GE(index.nm.back(), 830.0) << name;
    }
    // Gold at a tabulated wavelength: Johnson & Christy's row 0.5486 um, n 0.43, k 2.455.
    EXPECT_NEAR(spectral::conductor("gold").at(548.6).real(), 0.43, 1e-12);
    EXPECT_NEAR(spectral::conductor("gold").at(548.6).imag(), 2.455, 1e-12);
}

TEST(SpectralMetals, MalformedDataIsOneLineNamingTheFileAndLine) {
    auto problem = [](const std::string& text) {
        try {
            spectral::parse_conductor(text, "x.nk");
        } catch (const spectral::SpectralError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(problem("# c\n0.3 1 2\n0.9 1\n"), "x.nk: line 3: expected \"wavelength_um n k\"");
    EXPECT_EQ(problem("0.3 1 2\n0.2 1 2\n"), "x.nk: line 2: wavelengths must increase");
    EXPECT_EQ(problem("0.3 -1 2\n0.9 1 2\n"), "x.nk: line 1: needs finite numbers, n > 0 and k >= 0");
    EXPECT_EQ(problem("0.4 1 2\n0.9 1 2\n"), "x.nk: needs rows covering 360-830 nm");
    EXPECT_THROW(spectral::conductor("brass"), spectral::SpectralError);
}

// Eq. 19 with k = 0 is the dielectric eq. 19 the microfacet model uses (reference/classic.h).
TEST(SpectralMetals, ConductorFresnelWithNoAbsorptionIsTheDielectricEq19) {
    for (double n : {1.0, 1.2, 1.5, 2.4, 4.0})
        for (int i = 0; i <= 100; ++i) {
            const double c = i / 100.0;
            EXPECT_NEAR(spectral::conductor_fresnel({n, 0.0}, c), ref::dielectric_F(n, c), 1e-12)
                << "n " << n << ", cos " << c;
        }
}

TEST(SpectralMetals, FresnelAtNormalIncidenceIsRAndOneAtGrazing) {
    for (const std::string& name : spectral::conductor_names())
        for (double nm = 360.0; nm <= 830.0; nm += 5.0) {
            const std::complex<double> eta = spectral::conductor(name).at(nm);
            EXPECT_NEAR(spectral::conductor_fresnel(eta, 1.0), spectral::normal_reflectance(eta), 1e-12);
            EXPECT_EQ(spectral::conductor_fresnel(eta, 0.0), 1.0);
        }
}

// Energy: no wavelength reflects more than arrives, at any angle, so no pair
// reflects more luminance than its light brings (a channel of C0 may pass 1 —
// gold's red, 1.04 — where the reflected colour lies outside sRGB's gamut).
TEST(SpectralMetals, ReflectanceNeverExceedsOne) {
    for (const std::string& name : spectral::conductor_names()) {
        const spectral::ComplexIndex& index = spectral::conductor(name);
        for (double nm = 360.0; nm <= 830.0; nm += 5.0)
            for (int i = 0; i <= 200; ++i) {
                const double F = spectral::conductor_fresnel(index.at(nm), i / 200.0);
                EXPECT_GE(F, 0.0);
                EXPECT_LE(F, 1.0) << name << " " << nm << " nm, cos " << i / 200.0;
            }
        for (double kelvin : {1000.0, 3200.0, 40000.0}) {
            const spectral::Power light = spectral::light_power(kelvin, "");
            for (double c : {0.0, 0.05, 0.3, 1.0}) {
                const double reflected =
                    spectral::xyz_of([&](double nm) { return light(nm) * spectral::conductor_fresnel(index.at(nm), c); }).y;
                EXPECT_LE(reflected, spectral::xyz_of(light).y * (1.0 + 1e-12)) << name << " " << kelvin << " K";
            }
        }
    }
}

// The renderer's D65 colours against scripts/conductor-colours (python, its own
// reading of the same files: tests/data/conductor-colours.txt).
TEST(SpectralMetals, D65ColoursMatchTheSeparateScript) {
    std::ifstream file(std::string(M3055_SOURCE_DIR) + "/tests/data/conductor-colours.txt");
    ASSERT_TRUE(file) << "tests/data/conductor-colours.txt";
    std::string line;
    int rows = 0;
    while (std::getline(file, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream row(line);
        std::string name;
        glm::dvec3 expected;
        row >> name >> expected.r >> expected.g >> expected.b;
        const glm::dvec3 got = d65_normal_c0(name);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 2e-6) << name << " channel " << c;
        ++rows;
    }
    EXPECT_EQ(rows, int(spectral::conductor_names().size()));
}

// Cross-check with a published table: Adobe's "Metal material references" for the
// Adobe Standard Material (Substance 3D documentation, experienceleague.adobe.com/
// en/docs/substance-3d/general-knowledge/asm/metal-material-references), base
// colour F0 in linear Rec. 709. Chromium, nickel, silver and aluminium agree to
// 0.015 (chromium to 0.002); gold and copper to 0.07: other measurements of n, k,
// and that table clips red at 1 (gold's 1.04 here).
TEST(SpectralMetals, ColoursAgreeWithAPublishedTable) {
    const std::map<std::string, std::pair<glm::dvec3, double>> published = {
        {"chromium", {{0.5496, 0.5561, 0.5531}, 0.015}}, {"nickel", {{0.7014, 0.6382, 0.5593}, 0.015}},
        {"silver", {{0.9868, 0.9830, 0.9667}, 0.015}},   {"aluminium", {{0.9157, 0.9226, 0.9236}, 0.015}},
        {"gold", {{1.0000, 0.7099, 0.3148}, 0.07}},      {"copper", {{1.0000, 0.6504, 0.5274}, 0.07}},
    };
    for (const auto& [name, value] : published) {
        const glm::dvec3 got = d65_normal_c0(name);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], value.first[c], value.second) << name << " channel " << c;
    }
}

// The highlight of gold whitens toward grazing angles (eq. 19), which F(lambda, 0) cannot show.
TEST(SpectralMetals, FullFresnelWhitensGoldTowardGrazing) {
    Material gold = Material::of("metal");
    gold.set_choice("conductor", "gold");
    gold.set_choice("fresnel", "full");
    Light light;  // RGB white: D65
    auto spread = [](const glm::dvec3& c) { return (std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b})); };
    const glm::dvec3 head_on = ref::conductor_c0(gold, &light, 1.0), grazing = ref::conductor_c0(gold, &light, 0.05);
    EXPECT_LT(spread(grazing), 0.5 * spread(head_on));
    EXPECT_GT(grazing.b, head_on.b);
    gold.set_choice("fresnel", "normal");  // the paper's assumption: the same at every angle
    EXPECT_EQ(ref::conductor_c0(gold, &light, 0.05), ref::conductor_c0(gold, &light, 1.0));
}

// An RGB light stands for D65 scaled by its colour; a black body changes the metal's C0.
TEST(SpectralMetals, RgbLightsStandForD65AndKelvinLightsChangeC0) {
    Material copper = Material::of("metal_blinn");
    copper.set_choice("conductor", "copper");
    Light rgb;
    rgb.color = {1.0, 0.5, 0.2};
    const glm::dvec3 d65 = d65_normal_c0("copper");
    const glm::dvec3 c0 = ref::conductor_c0(copper, &rgb, 1.0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(c0[c], d65[c], 1e-12);
    Light warm;
    warm.temperature_k = 3200.0;
    EXPECT_GT(glm::length(ref::conductor_c0(copper, &warm, 1.0) - d65), 1e-3);
}

json scene_with(const json& material) {
    return {{"camera", {{"projection", "perspective"}, {"position", {0, 0, 4}}, {"target", {0, 0, 0}},
                        {"fov_y_deg", 30}}},
            {"objects", json::array({{{"center", {0, 0, 0}}, {"radius", 1}, {"material", material}}})}};
}

TEST(SpectralMetals, ConductorAndFresnelRoundTripAndOldScenesWriteAsBefore) {
    const json given = {{"model", "metal"}, {"conductor", "silver"}, {"fresnel", "full"}};
    const Scene scene = scene_from_json(scene_with(given), "t.json", LoadContext::trusted());
    const json written = scene_to_json(scene, PathWriting::absolute())["objects"][0]["material"];
    EXPECT_EQ(written["conductor"], "silver");
    EXPECT_EQ(written["fresnel"], "full");
    EXPECT_FALSE(written.contains("color"));
    EXPECT_EQ(scene_from_json(scene_to_json(scene, PathWriting::absolute()), "t.json", LoadContext::trusted())
                  .objects[0]
                  .material,
              scene.objects[0].material);

    const json plain = {{"model", "metal"}, {"color", {0.9, 0.6, 0.4}}};
    const json plain_written = scene_to_json(scene_from_json(scene_with(plain), "t.json", LoadContext::trusted()),
                                             PathWriting::absolute())["objects"][0]["material"];
    EXPECT_FALSE(plain_written.contains("conductor"));
    EXPECT_FALSE(plain_written.contains("fresnel"));
    EXPECT_TRUE(plain_written.contains("color"));
}

TEST(SpectralMetals, InvalidFieldsAreOneLineNamingTheObjectAndField) {
    auto problem = [](const json& material) {
        try {
            scene_from_json(scene_with(material), "t.json", LoadContext::trusted());
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(problem({{"model", "metal"}, {"conductor", "gold"}, {"color", {1, 1, 1}}}),
              "t.json: objects[0].material.conductor: the material gives both \"color\" and \"conductor\"; give one");
    EXPECT_EQ(problem({{"model", "metal"}, {"conductor", "none"}}), "t.json: objects[0].material.color: is required");
    EXPECT_NE(problem({{"model", "metal_phong"}, {"conductor", "gold"}, {"fresnel", "schlick"}})
                  .find("objects[0].material.fresnel: must be \"normal\" or \"full\""),
              std::string::npos);
    EXPECT_NE(problem({{"model", "highlight"}, {"color", {1, 1, 1}}, {"conductor", "gold"}})
                  .find("objects[0].material.conductor: not a parameter of model highlight"),
              std::string::npos);
}

}  // namespace
}  // namespace m3055
