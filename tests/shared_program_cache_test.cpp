// One program cache per context (gl/program.h), shared as the explorer shares
// it between its A and B renderers and the BRDF grid: a program is compiled
// once in the context, and a renderer drawing with programs another one built
// gives the same pixels.
#include "frame/renderer.h"
#include "gl/context.h"
#include "gl/program.h"
#include "passes/brdf_grid.h"
#include "scene/presets.h"

#include <gtest/gtest.h>

namespace m3055 {
namespace {

TEST(SharedProgramCache, TwoRenderersCompileTheGeneralProgramsOnceAndDrawTheSamePixels) {
    const auto context = HeadlessContext::create(Backend::automatic);
    ProgramCache programs(context->gl());
    Renderer a(context->gl(), programs), b(context->gl(), programs);
    a.warm_up_general_programs();
    const std::size_t compiled = programs.size();
    EXPECT_GT(compiled, 0u);
    b.warm_up_general_programs();
    EXPECT_EQ(programs.size(), compiled);
    EXPECT_EQ(b.compiled_programs(), compiled);

    Scene scene = default_scene();
    a.render(scene);
    Scene other = scene;  // B draws something else with the same programs in between
    other.objects[0].material = Material::of("metal");
    b.render(other);
    Renderer alone(context->gl());  // its own cache: what A must still match
    alone.render(scene);
    a.render(scene);
    EXPECT_EQ(a.read_display().pixels, alone.read_display().pixels);
}

TEST(SharedProgramCache, TheGridUsesTheProgramItsCompileCheckBuilt) {
    const auto context = HeadlessContext::create(Backend::automatic);
    ProgramCache programs(context->gl());
    BrdfGrid grid(context->gl(), programs);
    const Material material = Material::of("lambert");
    EXPECT_EQ(brdf_compile_error(programs, material), "");
    const std::size_t compiled = programs.size();
    EXPECT_EQ(compiled, 1u);
    const std::vector<float> f = grid.evaluate(material, {dvec3(0, 0, 1)}, {dvec3(0, 0, 1)});
    ASSERT_EQ(f.size(), 3u);
    EXPECT_GT(f[0], 0.0f);
    EXPECT_EQ(programs.size(), compiled);
}

// With deferral (the explorer's), a new specialization draws with the warmed-up
// general program and is built when idle; one whose stand-in was never built
// (area lights are not warmed up) is built at once: one compile, not two.
TEST(DeferredCompiles, TheGeneralProgramStandsInOnlyWhereItIsBuilt) {
    const auto context = HeadlessContext::create(Backend::automatic);
    Renderer renderer(context->gl());
    renderer.set_defer_compiles(true);
    renderer.warm_up_general_programs();
    const std::size_t warmed = renderer.compiled_programs();

    Scene scene = default_scene();
    scene.display.width = 64;
    scene.display.height = 40;
    scene.objects[0].material = Material::of("metal");
    renderer.render(scene);
    EXPECT_EQ(renderer.deferred_programs(), 1u);
    EXPECT_EQ(renderer.compiled_programs(), warmed);
    const std::vector<std::uint8_t> general = renderer.read_display().pixels;
    renderer.render_specialized(scene);
    EXPECT_EQ(renderer.deferred_programs(), 0u);
    EXPECT_EQ(renderer.compiled_programs(), warmed + 1);
    EXPECT_EQ(renderer.read_display().pixels, general);

    Scene area = scene;
    area.lights[0].type = LightType::disk;
    area.lights[0].position = {0.0, 3.0, 3.0};
    area.lights[0].normal = {0.0, -0.7071, -0.7071};
    area.lights[0].radius = 0.5;
    renderer.render(area);
    EXPECT_EQ(renderer.deferred_programs(), 0u);
    EXPECT_EQ(renderer.compiled_programs(), warmed + 2);  // the specialized one alone
}

}  // namespace
}  // namespace m3055
