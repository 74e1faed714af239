// Colours given as reflectance spectra (docs/spec.md#73-spectral-colours): eq. 2 per
// (material, light), metamerism, the scene format's "color_spectrum".
#include "models/model_table.h"
#include "reference/conductor.h"
#include "scene/load.h"
#include "scene/spectral_colour.h"
#include "spectral/cie_data.h"
#include "spectral/colorimetry.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <cmath>

namespace m3055 {
namespace {

using nlohmann::json;

// On the CIE table's 5 nm grid, so that the sums are exact in the samples.
ReflectanceSpectrum sampled(const std::function<double(double)>& f) {
    ReflectanceSpectrum s;
    for (double nm = 380.0; nm <= 780.0; nm += 5.0) s.nm.push_back(nm), s.values.push_back(f(nm));
    return s;
}

double bump(double nm, double centre) { return std::exp(-0.5 * std::pow((nm - centre) / 25.0, 2.0)); }

// A metameric black under D65: a mix of four bumps whose XYZ under D65 is 0
// (the fourth's weight 1, the other three solving the 3 x 3 system).
std::function<double(double)> d65_metameric_black() {
    const spectral::Spectrum& d65 = spectral::cie_illuminant("D65");
    const double centres[4] = {440.0, 520.0, 580.0, 640.0};
    glm::dvec3 xyz[4];
    for (int k = 0; k < 4; ++k) {
        // As the scene's spectrum will be read: sampled, held at 380 and 780 nm beyond.
        const ReflectanceSpectrum b = sampled([&](double nm) { return bump(nm, centres[k]); });
        xyz[k] = spectral::xyz_of([&](double nm) { return d65.at(nm) * b.at(nm); });
    }
    const glm::dvec3 a = glm::inverse(glm::dmat3(xyz[0], xyz[1], xyz[2])) * -xyz[3];
    return [=](double nm) {
        return a.x * bump(nm, centres[0]) + a.y * bump(nm, centres[1]) + a.z * bump(nm, centres[2]) +
               bump(nm, centres[3]);
    };
}

Light illuminant(const char* name) {
    Light light;
    light.illuminant = name;
    return light;
}

TEST(SpectralColours, TwoSpectraEqualUnderD65DifferUnderA) {
    const auto black = d65_metameric_black();
    double peak = 0.0;
    for (double nm = 380.0; nm <= 780.0; nm += 5.0) peak = std::max(peak, std::abs(black(nm)));
    const auto base = [](double nm) { return 0.5 + 0.1 * std::sin(nm / 40.0); };
    const ReflectanceSpectrum first = sampled(base);
    const ReflectanceSpectrum second = sampled([&](double nm) { return base(nm) + 0.35 / peak * black(nm); });
    for (double v : second.values) ASSERT_TRUE(v >= 0.0 && v <= 1.0);
    ASSERT_GT(glm::length(glm::dvec3(first.values[20], first.values[40], first.values[50]) -
                          glm::dvec3(second.values[20], second.values[40], second.values[50])),
              0.05);  // different spectra

    const Light d65 = illuminant("D65"), a = illuminant("A");
    const dvec3 under_d65 = spectrum_c0(first, &d65), other_under_d65 = spectrum_c0(second, &d65);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(under_d65[c], other_under_d65[c], 1e-9) << "channel " << c;
    const dvec3 under_a = spectrum_c0(first, &a), other_under_a = spectrum_c0(second, &a);
    EXPECT_GT(glm::length(under_a - other_under_a), 0.02) << "a metameric pair tells apart under A";

    // The CPU reference, which sums per wavelength on its own, agrees.
    Material m = Material::of("highlight");
    m.set_colour_spectrum(&second);
    const dvec3 ref_a = ref::spectral_c0(m, &a, 1.0), ref_d65 = ref::spectral_c0(m, &d65, 1.0);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(ref_a[c], other_under_a[c], 1e-12);
        EXPECT_NEAR(ref_d65[c], under_d65[c], 1e-9);
    }
}

TEST(SpectralColours, AFlatSpectrumIsItsGreyUnderEveryLight) {
    const ReflectanceSpectrum grey = sampled([](double) { return 0.4; });
    for (const char* name : {"A", "D65", "F11"}) {
        const Light light = illuminant(name);
        const dvec3 c0 = spectrum_c0(grey, &light);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(c0[c], 0.4, 1e-12) << name;
    }
}

json scene_with(const json& material) {
    return {{"camera", {{"projection", "perspective"}, {"position", {0, 0, 4}}, {"target", {0, 0, 0}},
                        {"fov_y_deg", 30}}},
            {"objects", json::array({{{"center", {0, 0, 0}}, {"radius", 1}, {"material", material}}})}};
}

std::string problem(const json& material) {
    try {
        scene_from_json(scene_with(material), "t.json");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

TEST(SpectralColours, LoadsWritesAndShowsItsD65Colour) {
    const json spectrum = {{"nm", {380, 500, 600, 780}}, {"values", {0.1, 0.2, 0.7, 0.9}}};
    const Scene scene = scene_from_json(scene_with({{"model", "metal_phong"}, {"color_spectrum", spectrum}}), "t.json");
    const Material& m = scene.objects[0].material;
    ASSERT_NE(m.colour_spectrum(), nullptr);
    EXPECT_EQ(m.colour_spectrum()->nm, (std::vector<double>{380, 500, 600, 780}));
    EXPECT_NEAR(m.colour_spectrum()->at(550.0), 0.45, 1e-12);
    const dvec3 d65 = spectrum_d65_rgb(*m.colour_spectrum());
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m.vec3("color")[c], std::clamp(d65[c], 0.0, 1.0), 1e-12);
    const json written = scene_to_json(scene)["objects"][0]["material"];
    EXPECT_EQ(written["color_spectrum"], spectrum);
    EXPECT_FALSE(written.contains("color"));
    EXPECT_EQ(scene_from_json(scene_to_json(scene), "t.json").objects[0].material, m);
}

TEST(SpectralColours, ModelSwitchesKeepTheSpectrumWhereAColourTakesOne) {
    Material m = Material::of("highlight");
    const ReflectanceSpectrum s = sampled([](double nm) { return nm > 550 ? 0.8 : 0.1; });
    m.set_colour_spectrum(&s);
    EXPECT_NE(with_model(m, model_table().get("metal")).colour_spectrum(), nullptr);
    EXPECT_EQ(with_model(m, model_table().get("lambert")).colour_spectrum(), nullptr);
}

TEST(SpectralColours, InvalidSpectraAreOneLineNamingTheField) {
    const json good = {{"nm", {380, 780}}, {"values", {0.1, 0.2}}};
    EXPECT_EQ(problem({{"model", "highlight"}, {"color", {1, 1, 1}}, {"color_spectrum", good}}),
              "t.json: objects[0].material.color_spectrum: the material gives both \"color\" and \"color_spectrum\"; "
              "give one");
    EXPECT_EQ(problem({{"model", "metal"}, {"conductor", "gold"}, {"color_spectrum", good}}),
              "t.json: objects[0].material.conductor: the material gives both \"color_spectrum\" and \"conductor\"; "
              "give one");
    EXPECT_EQ(problem({{"model", "highlight"}, {"color_spectrum", {{"nm", {380, 450, 450}}, {"values", {0, 0, 0}}}}}),
              "t.json: objects[0].material.color_spectrum.nm[2]: must be greater than the wavelength before it (450)");
    EXPECT_NE(problem({{"model", "highlight"}, {"color_spectrum", {{"nm", {370, 450}}, {"values", {0, 0}}}}})
                  .find("objects[0].material.color_spectrum.nm[0]: must be in [380, 780]"),
              std::string::npos);
    EXPECT_NE(problem({{"model", "highlight"}, {"color_spectrum", {{"nm", {380, 450}}, {"values", {0, 1.5}}}}})
                  .find("objects[0].material.color_spectrum.values[1]: must be in [0, 1]"),
              std::string::npos);
    EXPECT_NE(problem({{"model", "highlight"}, {"color_spectrum", {{"nm", {380, 450}}, {"values", {0}}}}})
                  .find("objects[0].material.color_spectrum.values"),
              std::string::npos);
    EXPECT_NE(problem({{"model", "lambert"}, {"kd", {1, 1, 1}}, {"color_spectrum", good}}).find("color_spectrum"),
              std::string::npos);
}

}  // namespace
}  // namespace m3055
