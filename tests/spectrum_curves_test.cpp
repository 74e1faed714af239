// The spectra in use (docs/spec.md#74-the-spectra-in-use): the curves the
// explorer's Spectra plot and `m3055 plot spectrum` draw, from one function
// (spectral::spectrum_curves, picked by scene/spectrum_view.h).
#include "models/material.h"
#include "scene/conductor_use.h"
#include "scene/light_colour.h"
#include "scene/spectrum_view.h"
#include "spectral/blackbody.h"
#include "spectral/cie_data.h"
#include "spectral/colorimetry.h"
#include "spectral/spectrum.h"
#include "spectral/spectrum_curves.h"

#include <gtest/gtest.h>

#include <cmath>

namespace m3055 {
namespace {

// Wien's displacement law: lambda_max T = b, b = 2.897771955e-3 m K (CODATA 2018, exact).
double wien_peak_nm(double kelvin) { return 2.897771955e6 / kelvin; }

Light kelvin_light(double kelvin) {
    Light light;
    light.temperature_k = kelvin;
    return light;
}

TEST(SpectrumCurves, TheRangeIsTheVisible380To780Every5Nm) {
    const spectral::SpectrumCurves c = spectral::spectrum_curves(spectral::light_power(0.0, "D65"), nullptr);
    ASSERT_EQ(c.nm.size(), 81u);
    EXPECT_EQ(c.nm.front(), 380.0);
    EXPECT_EQ(c.nm.back(), 780.0);
    EXPECT_EQ(c.light.size(), c.nm.size());
    EXPECT_TRUE(c.reflectance.empty());
}

TEST(SpectrumCurves, BlackBodiesPeakWhereWiensLawSays) {
    for (double kelvin : {4000.0, 5000.0, 6500.0}) {
        const Light light = kelvin_light(kelvin);
        const spectral::SpectrumCurves c = spectrum_view(&light, nullptr).curves;
        // The 5 nm samples put the peak within half a step of the law's wavelength.
        EXPECT_NEAR(spectral::peak_nm(c.nm, c.light), wien_peak_nm(kelvin), 2.5) << kelvin << " K";
    }
    // 6500 K: 445.8 nm, inside the range; 3000 K peaks at 966 nm: the curve rises to 780.
    const Light warm = kelvin_light(3000.0);
    const spectral::SpectrumCurves c = spectrum_view(&warm, nullptr).curves;
    EXPECT_EQ(spectral::peak_nm(c.nm, c.light), 780.0);
    for (std::size_t i = 1; i < c.light.size(); ++i) EXPECT_GT(c.light[i], c.light[i - 1]) << c.nm[i] << " nm";
}

TEST(SpectrumCurves, LightsAreAtLuminanceOneInUnitsWhereEIsOne) {
    const spectral::SpectrumCurves e = spectral::spectrum_curves(spectral::light_power(0.0, "E"), nullptr);
    // colord's E table starts at 380 nm (0 below, where y-bar is below 4e-5): 2e-6 of its luminance is missing.
    for (double v : e.light) EXPECT_NEAR(v, 1.0, 1e-5);
    // Every light plots with E's luminance: sum y-bar S dlambda over the observer's table.
    const double y_e = spectral::xyz_of([](double) { return 1.0; }).y;
    for (const Light& light : {kelvin_light(1000.0), kelvin_light(3200.0), kelvin_light(40000.0), Light{}}) {
        const spectral::SpectrumCurves c = spectrum_view(&light, nullptr).curves;
        const spectral::Power raw = spectral::light_power(light.temperature_k, light.illuminant);
        const double scale = c.light[40] / raw(c.nm[40]);
        EXPECT_NEAR(spectral::xyz_of([&](double nm) { return scale * raw(nm); }).y, y_e, 1e-9 * y_e);
        for (std::size_t i = 0; i < c.nm.size(); i += 10) EXPECT_NEAR(c.light[i], scale * raw(c.nm[i]), 1e-12);
    }
}

TEST(SpectrumCurves, AnRgbLightIsD65AsTheRendererTakesIt) {
    Light rgb;
    rgb.color = {1.0, 0.5, 0.25};
    Light d65;
    d65.illuminant = "D65";
    const SpectrumView a = spectrum_view(&rgb, nullptr), b = spectrum_view(&d65, nullptr);
    EXPECT_EQ(a.curves.light, b.curves.light);
    EXPECT_NE(a.light_label.find("D65 (an RGB light"), std::string::npos) << a.light_label;
    EXPECT_EQ(b.light_label, "CIE illuminant D65");
    EXPECT_EQ(spectrum_view(nullptr, nullptr).light_label, "D65 (no light: the display's white)");
    const Light k = kelvin_light(3200.0);
    EXPECT_EQ(spectrum_view(&k, nullptr).light_label, "black body 3200 K");
}

// Each curve is drawn in its spectrum's own colour: the light's as the
// renderer uses it, the reflectance's under D65 (gold's is the colour that
// stands for it in the explorer, scene/conductor_use.h).
TEST(SpectrumCurves, EachSpectrumCarriesItsOwnColour) {
    Light warm;  // as the loader and the explorer make it: its colour from its spectrum
    std::string error;
    ASSERT_TRUE(set_temperature(warm, 3200.0, &error)) << error;
    const SpectrumView light_only = spectrum_view(&warm, nullptr);
    EXPECT_EQ(light_only.light_colour, warm.color);
    EXPECT_GT(warm.color.r, warm.color.b) << "a warm light";
    EXPECT_EQ(light_only.reflectance_colour, dvec3(0.0)) << "no reflectance, no colour";
    Material gold = Material::of("metal");
    gold.set_choice("conductor", "gold");
    const dvec3 c = spectrum_view(&warm, &gold).reflectance_colour;
    const dvec3 expected = conductor_d65_colour("gold");
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(c[i], expected[i], 1e-9) << i;
    EXPECT_EQ(spectrum_view(nullptr, nullptr).light_colour, dvec3(1.0)) << "no light: the display's white";
}

TEST(SpectrumCurves, GoldsReflectanceRisesPast550NmAsItsDataFileHasIt) {
    Material gold = Material::of("metal");
    gold.set_choice("conductor", "gold");
    const SpectrumView view = spectrum_view(nullptr, &gold);
    EXPECT_EQ(view.reflectance_label, "gold, R(lambda) at normal incidence");
    const auto& c = view.curves;
    ASSERT_EQ(c.reflectance.size(), c.nm.size());
    const auto R = [&](double nm) { return c.reflectance[std::size_t(std::lround((nm - 380.0) / 5.0))]; };
    // data/conductors/gold.nk rows 0.5486 um (n 0.43, k 2.455) and 0.5821 um (0.29, 2.863),
    // linearly interpolated to 550 nm, then ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2).
    const double t = (550.0 - 548.6) / (582.1 - 548.6);
    const double n = 0.43 + t * (0.29 - 0.43), k = 2.455 + t * (2.863 - 2.455);
    EXPECT_NEAR(R(550.0), ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k), 1e-12);
    // Low and flat in the blue (about 0.4), rising steeply from 500 nm, above 0.9 in the red.
    for (double nm = 380.0; nm <= 480.0; nm += 5.0) EXPECT_LT(R(nm), 0.45) << nm;
    for (double nm = 500.0; nm <= 700.0; nm += 5.0) EXPECT_GE(R(nm), R(nm - 5.0)) << nm;
    EXPECT_GT(R(550.0), R(500.0) + 0.25);
    for (double nm = 620.0; nm <= 780.0; nm += 5.0) EXPECT_GT(R(nm), 0.9) << nm;
}

TEST(SpectrumCurves, AColourSpectrumIsItsOwnValuesHeldAtTheEnds) {
    Material m = Material::of("highlight");
    ReflectanceSpectrum s;
    s.nm = {450.0, 550.0, 650.0};
    s.values = {0.1, 0.9, 0.3};
    m.set_colour_spectrum(&s);
    const SpectrumView view = spectrum_view(nullptr, &m);
    EXPECT_EQ(view.reflectance_label, "color_spectrum");
    EXPECT_TRUE(view.no_reflectance.empty());
    const auto& c = view.curves;
    EXPECT_DOUBLE_EQ(c.reflectance[0], 0.1);     // 380 nm: held
    EXPECT_DOUBLE_EQ(c.reflectance[14], 0.1);     // 450 nm: the first given value
    EXPECT_DOUBLE_EQ(c.reflectance[24], 0.5);     // 500 nm: halfway to 550's
    EXPECT_DOUBLE_EQ(c.reflectance[34], 0.9);     // 550 nm
    EXPECT_DOUBLE_EQ(c.reflectance.back(), 0.3);  // 780 nm: held
}

TEST(SpectrumCurves, AClassicModelsKdSpectrumIsNamedAsItsKey) {
    Material m = Material::of("phong");
    ReflectanceSpectrum s;
    s.nm = {400.0, 700.0};
    s.values = {0.2, 0.6};
    m.set_colour_spectrum(&s);
    const SpectrumView view = spectrum_view(nullptr, &m);
    EXPECT_EQ(view.reflectance_label, "kd_spectrum");
    EXPECT_DOUBLE_EQ(view.curves.reflectance[24], 0.2 + 0.4 * 100.0 / 300.0);  // 500 nm
}

TEST(SpectrumCurves, AnRgbColourHasNoReflectanceAndSaysWhy) {
    const Material m = Material::of("highlight");
    const SpectrumView view = spectrum_view(nullptr, &m);
    EXPECT_TRUE(view.curves.reflectance.empty());
    EXPECT_EQ(view.no_reflectance, "model highlight: an RGB colour, no spectrum");
    EXPECT_EQ(spectrum_view(nullptr, nullptr).no_reflectance, "no material");
}

TEST(SpectrumCurves, ALightWithNoLuminanceIsAnError) {
    EXPECT_THROW(spectral::spectrum_curves([](double) { return 0.0; }, nullptr), spectral::SpectralError);
}

}  // namespace
}  // namespace m3055
