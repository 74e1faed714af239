// Colours given as reflectance spectra (docs/spec.md#73-spectral-colours): eq. 2 per
// (material, light), metamerism, the scene format's "color_spectrum".
#include "models/model_table.h"
#include "reference/classic.h"
#include "reference/conductor.h"
#include "reference/reference.h"
#include "scene/load.h"
#include "scene/spectral_colour.h"
#include "spectral/cie_data.h"
#include "spectral/colorimetry.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
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
        scene_from_json(scene_with(material), "t.json", LoadContext::trusted());
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

TEST(SpectralColours, LoadsWritesAndShowsItsD65Colour) {
    const json spectrum = {{"nm", {380, 500, 600, 780}}, {"values", {0.1, 0.2, 0.7, 0.9}}};
    const Scene scene = scene_from_json(scene_with({{"model", "metal_phong"}, {"color_spectrum", spectrum}}), "t.json",
                                        LoadContext::trusted());
    const Material& m = scene.objects[0].material;
    ASSERT_NE(m.colour_spectrum(), nullptr);
    EXPECT_EQ(m.colour_spectrum()->nm, (std::vector<double>{380, 500, 600, 780}));
    EXPECT_NEAR(m.colour_spectrum()->at(550.0), 0.45, 1e-12);
    const dvec3 d65 = spectrum_d65_rgb(*m.colour_spectrum());
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m.vec3("color")[c], std::clamp(d65[c], 0.0, 1.0), 1e-12);
    const json written = scene_to_json(scene, PathWriting::absolute())["objects"][0]["material"];
    EXPECT_EQ(written["color_spectrum"], spectrum);
    EXPECT_FALSE(written.contains("color"));
    EXPECT_EQ(scene_from_json(scene_to_json(scene, PathWriting::absolute()), "t.json", LoadContext::trusted())
                  .objects[0]
                  .material,
              m);
}

TEST(SpectralColours, ModelSwitchesKeepTheSpectrumWhereAColourTakesOne) {
    Material m = Material::of("highlight");
    const ReflectanceSpectrum s = sampled([](double nm) { return nm > 550 ? 0.8 : 0.1; });
    m.set_colour_spectrum(&s);
    EXPECT_NE(with_model(m, model_table().get("metal")).colour_spectrum(), nullptr);
    // The classic models take it as kd_spectrum (their "kd" carries "color").
    const Material lambert = with_model(m, model_table().get("lambert"));
    ASSERT_NE(lambert.colour_spectrum(), nullptr);
    EXPECT_EQ(*lambert.colour_spectrum(), s);
    EXPECT_EQ(lambert.vec3("kd"), m.vec3("color"));
}

TEST(SpectralColours, ClassicModelsTakeKdAsASpectrumLoadWriteAndDefaultKaToItsD65Colour) {
    const json spectrum = {{"nm", {380, 500, 600, 780}}, {"values", {0.1, 0.2, 0.7, 0.9}}};
    for (const char* model : {"lambert", "oren_nayar", "phong", "microfacet", "ward", "heidrich_seidel"}) {
        const Scene scene = scene_from_json(scene_with({{"model", model}, {"kd_spectrum", spectrum}}), "t.json",
                                            LoadContext::trusted());
        const Material& m = scene.objects[0].material;
        ASSERT_NE(m.colour_spectrum(), nullptr) << model;
        const dvec3 d65 = spectrum_d65_rgb(*m.colour_spectrum());
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(m.vec3("kd")[c], std::clamp(d65[c], 0.0, 1.0), 1e-12) << model;
        EXPECT_EQ(m.vec3("ka"), m.vec3("kd")) << model << ": ka defaults to kd";
        const json written = scene_to_json(scene, PathWriting::absolute())["objects"][0]["material"];
        EXPECT_EQ(written["kd_spectrum"], spectrum) << model;
        EXPECT_FALSE(written.contains("kd")) << model;
        EXPECT_EQ(scene_from_json(scene_to_json(scene, PathWriting::absolute()), "t.json", LoadContext::trusted())
                      .objects[0]
                      .material,
                  m)
            << model;
    }
    // Without it a classic material is written as before.
    const Scene plain =
        scene_from_json(scene_with({{"model", "phong"}, {"kd", {0.5, 0.5, 0.5}}}), "t.json", LoadContext::trusted());
    EXPECT_FALSE(scene_to_json(plain, PathWriting::absolute())["objects"][0]["material"].contains("kd_spectrum"));
}

TEST(SpectralColours, AClassicKdSpectrumIsItsColourPerLightInTheReference) {
    const ReflectanceSpectrum s = sampled([](double nm) { return 0.1 + 0.8 * bump(nm, 600.0); });
    Material spectral = Material::of("phong");
    spectral.set_colour_spectrum(&s);
    spectral.set_number("shininess", 20);
    ref::SurfacePoint point;
    point.P = {0, 0, 1}, point.N = {0, 0, 1}, point.V = glm::normalize(dvec3(0.3, 0, 1));
    Light a = illuminant("A");
    a.color = {1.3, 0.9, 0.4};  // as the loader sets it (any colour: the same in both sums below)
    a.direction = glm::normalize(dvec3(1, 1, 1));
    const std::vector<Light> lights = {a};
    // The same as an RGB kd equal to the spectrum's colour under A (eq. 2 for the pair).
    Material rgb = spectral;
    rgb.set_colour_spectrum(nullptr);
    rgb.set_vec3("kd", spectrum_c0(s, &a));
    const dvec3 got = ref::shade_classic(spectral, lights, point, dvec3(0.0));
    const dvec3 want = ref::shade_classic(rgb, lights, point, dvec3(0.0));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-12) << c;
    // Not the product of RGBs: the material's D65 colour under A's RGB gives another colour.
    rgb.set_vec3("kd", spectrum_d65_rgb(s));
    EXPECT_GT(glm::length(ref::shade_classic(rgb, lights, point, dvec3(0.0)) - got), 1e-3);
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
    EXPECT_EQ(problem({{"model", "phong"}, {"kd", {1, 1, 1}}, {"kd_spectrum", good}}),
              "t.json: objects[0].material.kd_spectrum: the material gives both \"kd\" and \"kd_spectrum\"; give one");
    EXPECT_NE(problem({{"model", "lambert"}, {"kd_spectrum", {{"nm", {380, 450}}, {"values", {0, 1.5}}}}})
                  .find("objects[0].material.kd_spectrum.values[1]: must be in [0, 1]"),
              std::string::npos);
    EXPECT_NE(problem({{"model", "highlight"}, {"kd_spectrum", good}}).find("kd_spectrum"), std::string::npos);
}

}  // namespace
}  // namespace m3055
