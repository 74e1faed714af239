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

}  // namespace
}  // namespace m3055
