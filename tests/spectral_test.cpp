// Spectral lights (docs/spec.md#71-spectral-lights): the CGATS reader,
// the CIE data from colord-data, Planck's law to XYZ to linear sRGB, and the
// scene format's "temperature_k" and "illuminant".
#include "reference/reference.h"
#include "scene/load.h"
#include "spectral/blackbody.h"
#include "spectral/cgats.h"
#include "spectral/cie_data.h"
#include "spectral/colorimetry.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>

namespace m3055 {
namespace {

using nlohmann::json;
using test::TempDir;

// Published chromaticities of the Planckian locus (CIE 1931 2-degree observer):
//  - A. R. Robertson, "Computation of correlated color temperature and distribution
//    temperature", J. Opt. Soc. Am. 58 (1968) 1528-1535, Table 1 (reprinted in
//    Wyszecki & Stiles, Color Science, 2nd ed. 1982, Table 1(3.11)): CIE 1960 (u, v)
//    at 500 mired (2000 K) u = 0.30505, v = 0.35907 and at 100 mired (10000 K)
//    u = 0.19032, v = 0.29326; x = 3u / (2u - 8v + 4), y = 2v / (2u - 8v + 4).
//  - B. Kang, O. Moon, C. Hong, H. Lee, B. Cho, Y. Kim, "Design of advanced color
//    temperature control system for HDTV applications", J. Korean Phys. Soc. 41
//    (2002) 865-871: cubic fits of x(T) and y(x) to the locus, 1667-25000 K (the
//    values not on Robertson's 25-mired grid: 3200, 5600, 6500 K).
glm::dvec2 xy_of_uv(double u, double v) {
    const double d = 2.0 * u - 8.0 * v + 4.0;
    return {3.0 * u / d, 2.0 * v / d};
}
glm::dvec2 kang_2002(double t) {
    const double x = t <= 4000.0 ? -0.2661239e9 / (t * t * t) - 0.2343589e6 / (t * t) + 0.8776956e3 / t + 0.179910
                                 : -3.0258469e9 / (t * t * t) + 2.1070379e6 / (t * t) + 0.2226347e3 / t + 0.240390;
    const double y = t <= 2222.0   ? -1.1063814 * x * x * x - 1.34811020 * x * x + 2.18555832 * x - 0.20219683
                     : t <= 4000.0 ? -0.9549476 * x * x * x - 1.37418593 * x * x + 2.09137015 * x - 0.16748867
                                   : 3.0817580 * x * x * x - 5.87338670 * x * x + 3.75112997 * x - 0.37001483;
    return {x, y};
}

glm::dvec2 blackbody_xy(double kelvin) {
    return spectral::chromaticity(spectral::xyz_of([kelvin](double nm) { return spectral::planck(nm, kelvin); }));
}

TEST(Spectral, BlackbodyChromaticitiesMatchPublishedValuesWithin1e3) {
    struct Published {
        double kelvin;
        glm::dvec2 xy;
        const char* source;
    };
    const Published published[] = {{2000.0, xy_of_uv(0.30505, 0.35907), "Robertson 1968"},
                                   {3200.0, kang_2002(3200.0), "Kang et al. 2002"},
                                   {5600.0, kang_2002(5600.0), "Kang et al. 2002"},
                                   {6500.0, kang_2002(6500.0), "Kang et al. 2002"},
                                   {10000.0, xy_of_uv(0.19032, 0.29326), "Robertson 1968"}};
    for (const Published& p : published) {
        const glm::dvec2 xy = blackbody_xy(p.kelvin);
        EXPECT_NEAR(xy.x, p.xy.x, 1e-3) << p.kelvin << " K against " << p.source;
        EXPECT_NEAR(xy.y, p.xy.y, 1e-3) << p.kelvin << " K against " << p.source;
        std::printf("%6.0f K: x %.5f y %.5f, %s x %.5f y %.5f, error %.1e %.1e\n", p.kelvin, xy.x, xy.y, p.source,
                    p.xy.x, p.xy.y, std::abs(xy.x - p.xy.x), std::abs(xy.y - p.xy.y));
    }
}

TEST(Spectral, D65IsTheDisplaysWhiteAtLuminanceOne) {
    const glm::dvec3 rgb = spectral::illuminant_rgb("D65");
    EXPECT_NEAR(rgb.r, 1.0, 1e-4);
    EXPECT_NEAR(rgb.g, 1.0, 1e-4);
    EXPECT_NEAR(rgb.b, 1.0, 1e-4);
    std::printf("D65: R %.7f G %.7f B %.7f\n", rgb.r, rgb.g, rgb.b);
    // The CIE's own D65 chromaticity (CIE 15:2004 Table T.3): 0.31272, 0.32903.
    const glm::dvec2 xy = spectral::chromaticity(spectral::xyz_of(spectral::cie_illuminant("D65")));
    // (0.312712, 0.329008 from the 5 nm tables here; the CIE's from 1 nm data.)
    EXPECT_NEAR(xy.x, 0.31272, 3e-5);
    EXPECT_NEAR(xy.y, 0.32903, 3e-5);
}

// A white Lambert sphere (K_diff = 1) lit head-on by D65 at intensity 1: the
// CPU reference's linear value at the sphere's centre is N.L = 1 times the light.
TEST(Spectral, D65OnAWhiteLambertSurfaceIsWhite) {
    const json doc = json::parse(R"({
      "display": {"width": 33, "height": 33, "bits": 8},
      "camera": {"projection": "orthographic", "position": [0, 0, 5], "target": [0, 0, 0], "height": 2.5},
      "lights": [{"type": "directional", "direction": [0, 0, 1], "intensity": 1, "illuminant": "D65"}],
      "objects": [{"shape": "sphere", "center": [0, 0, 0], "radius": 1,
                   "material": {"model": "lambert", "kd": [1, 1, 1], "ka": [0, 0, 0]}}]})");
    const Scene scene = scene_from_json(doc, "d65.json", LoadContext::trusted());
    const ref::ReferenceImage image = ref::render_reference(scene);
    const std::size_t centre = (16 * 33 + 16) * 3;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.rgb[centre + c], 1.0, 1e-4) << "channel " << c;
}

TEST(Spectral, LightsHaveLuminanceOneAndWarmerMeansRedder) {
    double previous_ratio = -1.0;
    for (double kelvin : {1000.0, 2000.0, 3200.0, 5600.0, 6500.0, 10000.0, 40000.0}) {
        const glm::dvec3 rgb = spectral::temperature_rgb(kelvin);
        EXPECT_NEAR(spectral::luminance(rgb), 1.0, 1e-12) << kelvin;
        EXPECT_GE(std::min({rgb.r, rgb.g, rgb.b}), 0.0) << kelvin;  // clipped to the gamut
        const double ratio = rgb.b / rgb.r;  // bluer as it gets hotter
        EXPECT_GT(ratio, previous_ratio) << kelvin;
        previous_ratio = ratio;
    }
    for (const std::string& name : spectral::illuminant_names())
        EXPECT_NEAR(spectral::luminance(spectral::illuminant_rgb(name)), 1.0, 1e-12) << name;
    // Illuminant A is a 2856 K black body (CIE 15:2004 section 3.1).
    const glm::dvec3 a = spectral::illuminant_rgb("A"), bb = spectral::temperature_rgb(2856.0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], bb[c], 2e-3) << c;
}

// colord-data's 1 nm files (A, C, ...) name their fields SPEC_300000 ... (nm x 1000):
// the grid comes from SPECTRAL_START_NM and SPECTRAL_END_NM.
TEST(Spectral, CgatsGridComesFromTheStartAndEndKeywords) {
    const auto sets = spectral::parse_cgats_spectra(
        "SPECTRAL_START_NM\t300.0\nSPECTRAL_END_NM\t302.0\nBEGIN_DATA_FORMAT\n SPEC_300000 SPEC_301000 SPEC_302000\n"
        "END_DATA_FORMAT\nBEGIN_DATA\n 1 2 3\nEND_DATA\n",
        "a.sp");
    ASSERT_EQ(sets.size(), 1u);
    EXPECT_EQ(sets[0].start_nm, 300.0);
    EXPECT_EQ(sets[0].step_nm, 1.0);
    EXPECT_EQ(sets[0].at(301.5), 2.5);
    const spectral::Spectrum& a = spectral::cie_illuminant("A");
    EXPECT_EQ(a.start_nm, 300.0);
    EXPECT_EQ(a.step_nm, 1.0);
    EXPECT_NEAR(a.at(560.0), 1.0, 1e-3);  // CIE tables are 100 (here 1) at 560 nm
}

TEST(Spectral, CgatsReaderReadsRowsAndRefusesMalformedFilesInOneLine) {
    const std::string good =
        "SPECT\nDESCRIPTOR\t\"test\"\nBEGIN_DATA_FORMAT\n SPEC_400\tSPEC_410\tSPEC_420\nEND_DATA_FORMAT\n"
        "BEGIN_DATA\n 1.0\t2.0\t4.0\n 0.5 0.25 0\nEND_DATA\n";
    const auto sets = spectral::parse_cgats_spectra(good, "good.sp");
    ASSERT_EQ(sets.size(), 2u);
    EXPECT_EQ(sets[0].start_nm, 400.0);
    EXPECT_EQ(sets[0].step_nm, 10.0);
    EXPECT_EQ(sets[0].at(405.0), 1.5);
    EXPECT_EQ(sets[0].at(420.0), 4.0);
    EXPECT_EQ(sets[0].at(430.0), 0.0);
    EXPECT_EQ(sets[1].values, (std::vector<double>{0.5, 0.25, 0.0}));

    auto error_of = [](const std::string& text) {
        try {
            spectral::parse_cgats_spectra(text, "bad.sp");
        } catch (const spectral::SpectralError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string head = "BEGIN_DATA_FORMAT\n SPEC_400 SPEC_410\nEND_DATA_FORMAT\n";
    EXPECT_EQ(error_of(head + "BEGIN_DATA\n 1 2 3\nEND_DATA\n"), "bad.sp: line 5: a data row of 3 values, 2 fields");
    EXPECT_EQ(error_of(head + "BEGIN_DATA\n 1 nan\nEND_DATA\n"), "bad.sp: line 5: \"nan\" is not a finite number");
    EXPECT_EQ(error_of(head + "BEGIN_DATA\n 1 2\n"), "bad.sp: BEGIN_DATA without END_DATA");
    EXPECT_EQ(error_of(head), "bad.sp: no data rows (BEGIN_DATA ... END_DATA)");
    EXPECT_EQ(error_of("SPECTRAL_START_NM 400\n" + head + "BEGIN_DATA\n 1 2\nEND_DATA\n"),
              "bad.sp: SPECTRAL_START_NM and SPECTRAL_END_NM come together");
    EXPECT_EQ(error_of("BEGIN_DATA_FORMAT\n SAMPLE_ID SPEC_410\nEND_DATA_FORMAT\n"),
              "bad.sp: line 2: field \"SAMPLE_ID\" is not SPEC_<nm>");
    EXPECT_EQ(error_of("BEGIN_DATA_FORMAT\n SPEC_400 SPEC_410 SPEC_430\nEND_DATA_FORMAT\nBEGIN_DATA\n1 2 3\nEND_DATA\n"),
              "bad.sp: the SPEC_<nm> fields are not evenly spaced");
}

// ---- the scene format --------------------------------------------------------

json scene_with_lights(const json& lights) {
    return {{"camera", {{"projection", "perspective"}, {"position", {0, 0, 4.5}}, {"target", {0, 0, 0}}, {"fov_y_deg", 30}}},
            {"lights", lights},
            {"objects", json::array()}};
}

std::string load_error(const json& doc) {
    try {
        scene_from_json(doc, "s.json", LoadContext::trusted());
    } catch (const SceneError& e) {
        return e.what();
    }
    return "no error";
}

TEST(SpectralScene, KelvinAndIlluminantLightsGetTheirRgbAndSaveAsWritten) {
    const json doc = scene_with_lights(
        {{{"type", "directional"}, {"direction", {1, 1, 1}}, {"name", "key"}, {"temperature_k", 3200}},
         {{"type", "directional"}, {"direction", {-1, 0, 1}}, {"illuminant", "F11"}},
         {{"type", "directional"}, {"direction", {0, 1, 1}}, {"color", {1, 0.5, 0.25}}}});
    const Scene scene = scene_from_json(doc, "s.json", LoadContext::trusted());
    EXPECT_EQ(scene.lights[0].temperature_k, 3200.0);
    EXPECT_EQ(scene.lights[0].color, spectral::temperature_rgb(3200.0));
    EXPECT_GT(scene.lights[0].color.r, 1.0);  // luminance 1: a warm light's red exceeds 1
    EXPECT_EQ(scene.lights[1].illuminant, "F11");
    EXPECT_EQ(scene.lights[1].color, spectral::illuminant_rgb("F11"));
    EXPECT_EQ(scene.lights[2].color, glm::dvec3(1, 0.5, 0.25));

    const json saved = scene_to_json(scene, PathWriting::absolute());
    EXPECT_EQ(saved["lights"][0]["temperature_k"], 3200.0);
    EXPECT_FALSE(saved["lights"][0].contains("color"));
    EXPECT_EQ(saved["lights"][1]["illuminant"], "F11");
    EXPECT_FALSE(saved["lights"][1].contains("color"));
    const Scene again = scene_from_json(saved, "saved.json", LoadContext::trusted());
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(again.lights[i].color, scene.lights[i].color) << i;
}

TEST(SpectralScene, BadSpectralFieldsAreOneLineNamingTheLight) {
    const json base = {{"type", "directional"}, {"direction", {1, 1, 1}}};
    auto with = [&](const json& extra) {
        json light = base;
        light.update(extra);
        return scene_with_lights(json::array({light}));
    };
    EXPECT_EQ(load_error(with({{"name", "key"}, {"color", {1, 1, 1}}, {"temperature_k", 3200}})),
              "s.json: lights[0].temperature_k: light \"key\" gives both \"color\" and \"temperature_k\"; give one colour");
    EXPECT_EQ(load_error(with({{"color", {1, 1, 1}}, {"illuminant", "A"}})),
              "s.json: lights[0].illuminant: this light gives both \"color\" and \"illuminant\"; give one colour");
    EXPECT_EQ(load_error(with({{"temperature_k", 3200}, {"illuminant", "A"}})),
              "s.json: lights[0].illuminant: this light gives both \"temperature_k\" and \"illuminant\"; give one colour");
    EXPECT_EQ(load_error(with({{"temperature_k", 999}})), "s.json: lights[0].temperature_k: must be in [1000, 40000], got 999");
    EXPECT_EQ(load_error(with({{"temperature_k", "warm"}})), "s.json: lights[0].temperature_k: must be a number, got \"warm\"");
    const std::string bad_name = load_error(with({{"illuminant", "X66"}}));
    EXPECT_EQ(bad_name.rfind("s.json: lights[0].illuminant: must be \"A\", \"B\"", 0), 0u) << bad_name;
    EXPECT_NE(bad_name.find("\"F12\", got \"X66\""), std::string::npos) << bad_name;
    // A name one typo from a known one: that one first, then the list.
    EXPECT_EQ(load_error(with({{"illuminant", "D66"}})).rfind(
                  "s.json: lights[0].illuminant: got \"D66\": did you mean \"D65\"? (must be \"A\", \"B\"", 0),
              0u);
}

TEST(SpectralScene, AMissingDataFileIsOneLineNamingIt) {
    TempDir empty;
    setenv("M3055_COLORD_DIR", empty.path().c_str(), 1);
    const std::string error = load_error(scene_with_lights(
        json::array({{{"type", "directional"}, {"direction", {1, 1, 1}}, {"temperature_k", 3200}}})));
    unsetenv("M3055_COLORD_DIR");
    EXPECT_EQ(error.rfind("s.json: lights[0].temperature_k: cannot make its colour: " + empty.path() +
                              "/cmf/CIE1931-2deg-XYZ.cmf: ",
                          0),
              0u)
        << error;
    EXPECT_NE(error.find("(Debian package colord-data; scripts/setup installs it)"), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

}  // namespace
}  // namespace m3055
