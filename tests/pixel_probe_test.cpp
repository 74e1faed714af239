// The explorer's read-outs (renderer/analysis/pixel_probe.h) without a window:
// levels from PNG values, the level histogram, and the picker's rays. The
// probe against a headless render is in explorer_test.cpp (PixelProbeEqualsTheHeadlessRender).
#include "analysis/pixel_probe.h"
#include "scene/load.h"
#include "scene/spectral_colour.h"
#include "spectral/conductor.h"
#include "spectral/reflected_colour.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace m3055 {
namespace {

TEST(PixelProbe, LevelOfPngInvertsTheSpecsEncoding) {
    for (int bits = 1; bits <= 8; ++bits) {
        const int top = (1 << bits) - 1;
        for (int level = 0; level <= top; ++level) {
            const int png = static_cast<int>(std::lround(level * 255.0 / top));  // docs/spec.md#2-display
            EXPECT_EQ(level_of_png(png, bits), level) << bits << " bits";
        }
    }
}

TEST(PixelProbe, HistogramCountsEveryPixelOncePerChannel) {
    Rgb8Image image;
    image.width = 3;
    image.height = 2;
    image.pixels = {0, 0, 255, 8, 0, 255, 8, 16, 255, 255, 16, 255, 255, 16, 255, 0, 0, 255};
    const LevelHistogram h = level_histogram(image, 5);
    ASSERT_EQ(h.counts[0].size(), 32u);
    long total = 0;
    for (long n : h.counts[0]) total += n;
    EXPECT_EQ(total, 6);
    EXPECT_EQ(h.counts[0][0], 2);
    EXPECT_EQ(h.counts[0][1], 2);   // png 8 = level 1 of 31 (8.23 rounded)
    EXPECT_EQ(h.counts[0][31], 2);
    EXPECT_EQ(h.used[0], 3);
    EXPECT_EQ(h.used[1], 2);        // 0 and 16 (level 2)
    EXPECT_EQ(h.used[2], 1);
}

TEST(PixelProbe, PickerFindsTheObjectUnderAPixelAndItsNormal) {
    const Scene scene = load_scene_file(test::source_path("scenes/fig10.json"), LoadContext::trusted());
    const ScenePicker picker(scene);
    const int w = scene.display.width, h = scene.display.height;
    EXPECT_EQ(picker.pick(0, 0).object, -1);
    const PixelHit centre = picker.pick(w / 2, h / 2);
    ASSERT_GE(centre.object, 0);
    const Object& object = scene.objects[std::size_t(centre.object)];
    EXPECT_NEAR(glm::length(centre.P - object.center), object.radius, 1e-9) << "on the sphere";
    EXPECT_NEAR(glm::length(centre.N), 1.0, 1e-12);
    EXPECT_GT(glm::dot(centre.N, centre.V), 0.0) << "a front face";
    const std::vector<int> ids = picker.object_ids();
    ASSERT_EQ(ids.size(), std::size_t(w) * h);
    EXPECT_EQ(ids[std::size_t(h / 2) * w + w / 2], centre.object);
    for (int i = 0; i < static_cast<int>(scene.objects.size()); ++i)
        EXPECT_NE(std::find(ids.begin(), ids.end(), i), ids.end()) << "object " << i << " is on the display";
}

// A gold sphere under a 3200 K key, an RGB fill at half intensity and a light
// that is off, seen from +z (scene format as docs/spec.md#7-scene-files).
Scene gold_scene(const std::string& fresnel) {
    nlohmann::json doc = {
        {"display", {{"width", 64}, {"height", 40}}},
        {"camera", {{"projection", "perspective"}, {"position", {0, 0, 4.5}}, {"target", {0, 0, 0}}, {"fov_y_deg", 30}}},
        {"lights",
         {{{"type", "directional"}, {"direction", {1, 1, 1}}, {"temperature_k", 3200}, {"name", "key"}},
          {{"type", "directional"}, {"direction", {-1, 0, 0.3}}, {"color", {1.0, 0.5, 0.25}}, {"intensity", 0.5}},
          {{"type", "directional"}, {"direction", {0, 1, 1}}, {"enabled", false}}}},
        {"objects",
         {{{"shape", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1.0},
           {"material", {{"model", "metal"}, {"conductor", "gold"}, {"fresnel", fresnel}}}}}}};
    return scene_from_json(doc, "gold.json", LoadContext::trusted());
}

dvec3 gold_c0(const spectral::Power& light, double cos_theta, bool full) {
    const spectral::ComplexIndex& gold = spectral::conductor("gold");
    return spectral::reflected_c0(light, [&](double nm) {
        return full ? spectral::conductor_fresnel(gold.at(nm), cos_theta) : spectral::normal_reflectance(gold.at(nm));
    });
}

void expect_rgb(const dvec3& a, const dvec3& b, double tolerance, const std::string& what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], tolerance) << what << ", channel " << c;
}

TEST(PixelProbe, EachLightsColourForAConductorIsEq2ForThePairAndLightsThatAreOffAreLeftOut) {
    const Scene scene = gold_scene("normal");
    const ScenePicker picker(scene);
    const PixelHit hit = picker.pick(32, 20);
    ASSERT_EQ(hit.object, 0);
    const std::vector<PairColour> pairs = pair_colours(scene, hit);
    ASSERT_EQ(pairs.size(), 2u) << "the light that is off gives nothing";
    EXPECT_EQ(pairs[0].light, 0);
    EXPECT_EQ(pairs[0].name, "key");
    EXPECT_EQ(pairs[1].light, 1);
    EXPECT_FALSE(pairs[0].by_angle);
    // 3200 K: eq. 2 per wavelength; the RGB light stands for D65 (docs/spec.md#72-measured-metals).
    expect_rgb(pairs[0].c0, gold_c0(spectral::light_power(3200.0, ""), 1.0, false), 1e-12, "key");
    expect_rgb(pairs[1].c0, gold_c0(spectral::light_power(0.0, "D65"), 1.0, false), 1e-12, "fill");
    expect_rgb(pairs[0].lit, scene.lights[0].color * pairs[0].c0, 1e-12, "key's a c C0");
    expect_rgb(pairs[1].lit, 0.5 * dvec3(1.0, 0.5, 0.25) * pairs[1].c0, 1e-12, "fill's a c C0");
    EXPECT_GT(pairs[0].c0.r / pairs[0].c0.b, pairs[1].c0.r / pairs[1].c0.b) << "gold is redder under 3200 K";
    // The read-out: one line a light, after the pixel's lines.
    PixelProbe probe;
    probe.object = 0;
    probe.model = "metal";
    probe.pairs = pairs;
    const std::string text = probe.text();
    char key[160];
    std::snprintf(key, sizeof key, "\nlight 0 \"key\": C0_l %.3f %.3f %.3f  a_l c_l C0_l %.3f %.3f %.3f", pairs[0].c0.r,
                  pairs[0].c0.g, pairs[0].c0.b, pairs[0].lit.r, pairs[0].lit.g, pairs[0].lit.b);
    EXPECT_NE(text.find(key), std::string::npos) << text;
    EXPECT_NE(text.find("\nlight 1: C0_l "), std::string::npos) << text;
    EXPECT_EQ(text.find("light 2"), std::string::npos) << text;
    EXPECT_EQ(text.find("V.H"), std::string::npos) << "F(lambda, 0) does not depend on the angle";
}

TEST(PixelProbe, AreaAndSkyLightsAreReadTowardsTheEmittersCentreOrTheSkysUp) {
    Scene scene = gold_scene("normal");
    Light rect;
    rect.type = LightType::rect;
    rect.position = {0, 3, 3};
    rect.normal = glm::normalize(dvec3(0, -1, -1));
    rect.up = {0, 1, 0};
    Light sky;
    sky.type = LightType::sky;
    scene.lights = {rect, sky};
    const ScenePicker picker(scene);
    const PixelHit hit = picker.pick(32, 20);
    ASSERT_EQ(hit.object, 0);
    EXPECT_EQ(pair_colours(scene, hit).size(), 2u);
    RgbFloatImage raw;
    raw.width = scene.display.width, raw.height = scene.display.height;
    raw.pixels.assign(std::size_t(raw.width) * raw.height * 3, 0.0f);
    Rgb8Image display;
    display.width = raw.width, display.height = raw.height;
    display.pixels.assign(std::size_t(raw.width) * raw.height * 3, 0);
    const PixelProbe towards_rect = probe_pixel(scene, picker, raw, display, 32, 20, 0);
    ASSERT_TRUE(towards_rect.lit);
    EXPECT_NEAR(towards_rect.NoL, glm::dot(hit.N, glm::normalize(rect.position - hit.P)), 1e-12);
    const PixelProbe towards_sky = probe_pixel(scene, picker, raw, display, 32, 20, 1);
    EXPECT_NEAR(towards_sky.NoL, hit.N.y, 1e-12);
}

TEST(PixelProbe, WithTheFullEq19EachLightsColourIsTakenAtThePixelsVDotH) {
    const Scene scene = gold_scene("full");
    const ScenePicker picker(scene);
    const PixelHit centre = picker.pick(32, 20), rim = picker.pick(32, 35);
    ASSERT_EQ(centre.object, 0);
    ASSERT_EQ(rim.object, 0);
    for (const PixelHit& hit : {centre, rim}) {
        const std::vector<PairColour> pairs = pair_colours(scene, hit);
        ASSERT_EQ(pairs.size(), 2u);
        const dvec3 H_key = glm::normalize(glm::normalize(dvec3(1, 1, 1)) + hit.V);
        const dvec3 H_fill = glm::normalize(glm::normalize(dvec3(-1, 0, 0.3)) + hit.V);
        EXPECT_NEAR(pairs[0].cos_theta, glm::dot(hit.V, H_key), 1e-12);
        EXPECT_NEAR(pairs[1].cos_theta, glm::dot(hit.V, H_fill), 1e-12);
        EXPECT_GT(std::abs(pairs[0].cos_theta - pairs[1].cos_theta), 0.02);
        EXPECT_TRUE(pairs[0].by_angle);
        expect_rgb(pairs[0].c0, gold_c0(spectral::light_power(3200.0, ""), pairs[0].cos_theta, true), 1e-12, "key");
        expect_rgb(pairs[1].c0, gold_c0(spectral::light_power(0.0, "D65"), pairs[1].cos_theta, true), 1e-12, "fill");
        EXPECT_GT(glm::length(pairs[0].c0 - gold_c0(spectral::light_power(3200.0, ""), 1.0, true)), 1e-4)
            << "not the normal-incidence colour";
        PixelProbe probe;
        probe.pairs = pairs;
        EXPECT_NE(probe.text().find(" at V.H "), std::string::npos);
    }
}

TEST(PixelProbe, AColourSpectrumGivesItsColourPerLightAndAnRgbColourNone) {
    Scene scene = gold_scene("normal");
    Material highlight = Material::of("highlight");
    ReflectanceSpectrum spectrum;
    spectrum.nm = {400.0, 700.0};
    spectrum.values = {0.2, 0.8};
    highlight.set_colour_spectrum(&spectrum);
    scene.objects[0].material = highlight;
    const ScenePicker picker(scene);
    const PixelHit hit = picker.pick(32, 20);
    const std::vector<PairColour> pairs = pair_colours(scene, hit);
    ASSERT_EQ(pairs.size(), 2u);
    expect_rgb(pairs[0].c0, spectrum_c0(spectrum, &scene.lights[0]), 1e-12, "key");
    expect_rgb(pairs[1].c0, spectrum_c0(spectrum, &scene.lights[1]), 1e-12, "fill");
    EXPECT_FALSE(pairs[0].by_angle);

    EXPECT_EQ(pairs[0].symbol, "C0");
    // A classic model's kd_spectrum: K_diff per light, read out as kd_l.
    Material phong = Material::of("phong");
    phong.set_colour_spectrum(&spectrum);
    scene.objects[0].material = phong;
    const std::vector<PairColour> kd = pair_colours(scene, hit);
    ASSERT_EQ(kd.size(), 2u);
    EXPECT_EQ(kd[0].symbol, "kd");
    expect_rgb(kd[0].c0, spectrum_c0(spectrum, &scene.lights[0]), 1e-12, "phong key");
    PixelProbe probe;
    probe.pairs = kd;
    EXPECT_NE(probe.text().find("\nlight 0 \"key\": kd_l "), std::string::npos) << probe.text();
    EXPECT_NE(probe.text().find("  a_l c_l kd_l "), std::string::npos) << probe.text();

    scene.objects[0].material = Material::of("highlight");  // RGB: every light sees the same C0
    EXPECT_TRUE(pair_colours(scene, hit).empty());
    EXPECT_TRUE(pair_colours(scene, picker.pick(0, 0)).empty()) << "the background";
}

}  // namespace
}  // namespace m3055
