// The display's view transform (docs/spec.md#2-display): none (the M3055's
// levels of the linear value, every scene so far) or sRGB's encoding before
// the levels (a modern display, as other tools show colour). The CPU's
// quantization (image/quantize.h) and the GPU's post pass
// (glsl/passes/quantize.frag) agree; the scene format and `m3055 render
// --view-transform` carry it; a scene without it renders as before.
#include "frame/renderer.h"
#include "gpu_compare.h"
#include "image/image.h"
#include "image/quantize.h"
#include "scene/conductor_use.h"
#include "scene/load.h"
#include "scene/presets.h"
#include "test_paths.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>

namespace m3055 {
namespace {

TEST(ViewTransform, SrgbEncodingIsIec61966WithItsLinearToe) {
    EXPECT_DOUBLE_EQ(srgb_encode(0.0), 0.0);
    EXPECT_NEAR(srgb_encode(1.0), 1.0, 1e-15);
    EXPECT_NEAR(srgb_encode(0.5), 0.7353569830524495, 1e-12);
    EXPECT_NEAR(srgb_encode(0.0031308), 0.0031308 * 12.92, 1e-12) << "the toe ends where the curve starts";
    EXPECT_NEAR(1.055 * std::pow(0.0031308, 1.0 / 2.4) - 0.055, 0.0031308 * 12.92, 1e-7) << "continuous there";
    double last = -1.0;
    for (int i = 0; i <= 1000; ++i) {
        const double v = srgb_encode(i / 1000.0);
        EXPECT_GT(v, last) << i;
        last = v;
    }
}

TEST(ViewTransform, GoldsD65ColourReadsAsOtherToolsShowIt) {
    // Gold under D65 (scene/conductor_use.h, about (1.04, 0.73, 0.37)): the
    // M3055's levels show the linear value (a copper-looking (255, 186, 93) at
    // 8 bits), an sRGB display its encoding, the gold of other tools.
    const dvec3 gold = conductor_d65_colour("gold");
    int none[3], srgb[3];
    for (int c = 0; c < 3; ++c) {
        none[c] = level_to_png(quantize_level(gold[c], 8), 8);
        srgb[c] = level_to_png(quantize_level(gold[c], 8, true), 8);
    }
    EXPECT_EQ(none[0], 255);
    EXPECT_NEAR(none[1], 186, 1);
    EXPECT_NEAR(none[2], 93, 1);
    EXPECT_EQ(srgb[0], 255);
    EXPECT_NEAR(srgb[1], 221, 1);
    EXPECT_NEAR(srgb[2], 162, 1);
    std::printf("gold under D65: linear %.4f %.4f %.4f; PNG none %d %d %d, sRGB %d %d %d\n", gold.r, gold.g, gold.b,
                none[0], none[1], none[2], srgb[0], srgb[1], srgb[2]);
}

TEST(ViewTransform, TheSceneFormatCarriesItAndWritesItOnlyWhenSet) {
    nlohmann::json doc = scene_to_json(default_scene(), PathWriting::absolute());
    EXPECT_FALSE(doc["display"].contains("view_transform")) << "absent: none, every saved scene as before";
    doc["display"]["view_transform"] = "srgb";
    const Scene scene = scene_from_json(doc, "srgb.json", LoadContext::trusted());
    EXPECT_EQ(scene.display.view_transform, ViewTransform::srgb);
    EXPECT_EQ(scene_to_json(scene, PathWriting::absolute())["display"]["view_transform"], "srgb");
    doc["display"]["view_transform"] = "gamma";
    try {
        scene_from_json(doc, "bad.json", LoadContext::trusted());
        FAIL() << "an unknown transform is refused";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("bad.json: display.view_transform: must be"), std::string::npos) << e.what();
    }
}

// The background is drawn as it is: every background pixel is the transform's
// level of the colour, exactly; the sphere agrees with the reference's levels.
TEST(ViewTransform, TheGpusLevelsAreTheEncodedLinearValues) {
    Scene scene = default_scene();
    scene.display.bits = 8;
    scene.display.view_transform = ViewTransform::srgb;
    scene.background = {0.73, 0.37, 0.0031};
    Renderer& renderer = test::shared_renderer();
    renderer.set_shader_mode(ShaderMode::specialized);
    renderer.render(scene);
    const Rgb8Image display = renderer.read_display();
    for (int c = 0; c < 3; ++c)
        EXPECT_EQ(display.pixels[std::size_t(c)], level_to_png(quantize_level(scene.background[c], 8, true), 8))
            << "channel " << c << " of the top-left (background) pixel";
    const test::Comparison comparison = test::compare_gpu_with_reference(scene);
    EXPECT_GE(comparison.same_level_share, 0.995) << comparison.describe();
    EXPECT_LE(comparison.max_level_diff, 1) << comparison.describe();
}

TEST(ViewTransform, RenderTakesItFromTheCommandLineAndLeavesTheDefaultAsItWas) {
    test::TempDir dir;
    const std::string scene = test::source_path("scenes/spec_example.json");
    nlohmann::json doc = nlohmann::json::parse(test::read_text(scene));
    doc["display"]["view_transform"] = "srgb";
    test::write_text(dir.file("srgb.json"), doc.dump());
    ASSERT_EQ(test::run_m3055({"render", "--scene", scene, "--out", dir.file("flag.png"), "--view-transform", "srgb"})
                  .exit_code, 0);
    ASSERT_EQ(test::run_m3055({"render", "--scene", dir.file("srgb.json"), "--out", dir.file("key.png")}).exit_code, 0);
    ASSERT_EQ(test::run_m3055({"render", "--scene", scene, "--out", dir.file("plain.png")}).exit_code, 0);
    ASSERT_EQ(test::run_m3055({"render", "--scene", scene, "--out", dir.file("none.png"), "--view-transform", "none"})
                  .exit_code, 0);
    EXPECT_EQ(test::read_text(dir.file("flag.png")), test::read_text(dir.file("key.png")));
    EXPECT_EQ(test::read_text(dir.file("plain.png")), test::read_text(dir.file("none.png")));
    EXPECT_NE(test::read_text(dir.file("plain.png")), test::read_text(dir.file("flag.png")));
    const test::RunResult bad =
        test::run_m3055({"render", "--scene", scene, "--out", dir.file("x.png"), "--view-transform", "gamma"});
    EXPECT_NE(bad.exit_code, 0);
}

}  // namespace
}  // namespace m3055
