// Renderer::render_reduced, the explorer's preview of costly scenes: drawn at
// 1/divisor of the display's size and spread over the display's own pixels,
// each small pixel a divisor x divisor block, display and raw colour alike.
#include "frame/renderer.h"
#include "gl/context.h"
#include "scene/presets.h"

#include <gtest/gtest.h>

namespace m3055 {
namespace {

Scene sized(int width, int height) {
    Scene scene = default_scene();
    scene.display.width = width;
    scene.display.height = height;
    return scene;
}

TEST(RendererReduced, EachSmallPixelFillsABlockOfTheDisplaysSize) {
    const auto context = HeadlessContext::create(Backend::automatic);
    Renderer reduced(context->gl()), small(context->gl());
    reduced.render_reduced(sized(64, 40), 4);
    small.render(sized(16, 10));
    ASSERT_EQ(reduced.width(), 64);
    ASSERT_EQ(reduced.height(), 40);
    const Rgb8Image big = reduced.read_display(), little = small.read_display();
    const RgbFloatImage big_raw = reduced.read_raw(), little_raw = small.read_raw();
    int mismatches = 0, raw_mismatches = 0;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 3; ++c) {
                const std::size_t at = (std::size_t(y) * 64 + x) * 3 + c,
                                  from = (std::size_t(y / 4) * 16 + x / 4) * 3 + c;
                mismatches += big.pixels[at] != little.pixels[from];
                raw_mismatches += big_raw.pixels[at] != little_raw.pixels[from];
            }
    EXPECT_EQ(mismatches, 0);
    EXPECT_EQ(raw_mismatches, 0);
    // Not one flat colour: the blocks carry the scene.
    EXPECT_NE(little.pixels[(5 * 16 + 8) * 3], little.pixels[0]);
}

TEST(RendererReduced, DivisorOneIsTheRender) {
    const auto context = HeadlessContext::create(Backend::automatic);
    Renderer reduced(context->gl()), full(context->gl());
    reduced.render_reduced(sized(48, 30), 1);
    full.render(sized(48, 30));
    EXPECT_EQ(reduced.read_display().pixels, full.read_display().pixels);
}

TEST(RendererReduced, AFullRenderAfterAPreviewIsTheRender) {
    const auto context = HeadlessContext::create(Backend::automatic);
    Renderer renderer(context->gl()), full(context->gl());
    renderer.render_reduced(sized(48, 30), 3);
    renderer.render(sized(48, 30));
    full.render(sized(48, 30));
    EXPECT_EQ(renderer.read_display().pixels, full.read_display().pixels);
}

}  // namespace
}  // namespace m3055
