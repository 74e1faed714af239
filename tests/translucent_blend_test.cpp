// The translucent pass without dual-source blending (passes/translucent_blend.h):
// a multiply draw and an add draw per layer of fragments must give the same
// display levels as the one dual-source draw, byte for byte, for every
// translucent scene of the repository and for the cases that make a naive
// two-pass blend wrong: overlapping translucent spheres in one draw, hundreds
// of them on one pixel, a torus (two front faces on one pixel, drawn in
// stencil layers) and translucent meshes over and among spheres, in the
// specialized and general programs and in chunked draws. The unquantized
// colour is compared too: in float targets fl(fl(dst * t) + c) is the blend's
// own arithmetic, so it matches to the bit on llvmpipe.
#include "frame/renderer.h"
#include "gpu_compare.h"
#include "object_builders.h"
#include "models/model_table.h"
#include "scene/load.h"
#include "scene/presets.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace m3055 {
namespace {

namespace fs = std::filesystem;

using test::cube;
using test::cylinder;
using test::shared_renderer;
using test::sphere;
using test::torus;

struct Render {
    Rgb8Image display;
    RgbFloatImage raw;
};

Render render(const Scene& scene, TranslucentBlend blend, ShaderMode mode = ShaderMode::specialized,
              bool chunked = false) {
    Renderer& renderer = shared_renderer();
    renderer.set_translucent_blend(blend);
    renderer.set_shader_mode(mode);
    // A deadline far away: the draws go in chunks (passes/draw_chunks.h), nothing times out.
    if (chunked) renderer.set_deadline(std::chrono::steady_clock::now() + std::chrono::hours(1));
    renderer.render(scene);
    renderer.set_deadline(std::nullopt);
    renderer.set_shader_mode(ShaderMode::specialized);
    return {renderer.read_display(), renderer.read_raw()};
}

// Pixels whose display bytes differ between the two blends ("" when none).
std::string compare_blends(const Scene& scene, ShaderMode mode = ShaderMode::specialized, bool chunked = false) {
    const Render dual = render(scene, TranslucentBlend::dual_source, mode, chunked);
    const Render two = render(scene, TranslucentBlend::two_pass, mode, chunked);
    long display_diff = 0, raw_diff = 0;
    for (std::size_t i = 0; i < dual.display.pixels.size(); ++i) display_diff += dual.display.pixels[i] != two.display.pixels[i];
    for (std::size_t i = 0; i < dual.raw.pixels.size(); ++i) raw_diff += dual.raw.pixels[i] != two.raw.pixels[i];
    if (!display_diff && !raw_diff) return "";
    return std::to_string(display_diff) + " display bytes and " + std::to_string(raw_diff) + " raw floats differ";
}

bool has_translucent(const Scene& scene) {
    for (const Object& object : scene.objects)
        if (is_translucent(object.material)) return true;
    return false;
}

Material translucent(dvec3 color, double t_n, double t_p) {
    Material material = Material::of("translucent");
    material.set_vec3("color", color);
    material.set_number("t_n", t_n), material.set_number("t_p", t_p);
    return material;
}



// The default scene (camera, lights, an opaque sphere at the origin) at a small size.
Scene small_scene(std::vector<Object> more) {
    Scene scene = default_scene();
    scene.display.width = 96, scene.display.height = 64;
    for (Object& o : more) scene.objects.push_back(o);
    return scene;
}

TEST(TranslucentBlend, EveryTranslucentSceneOfTheRepositoryGivesIdenticalDisplayBothWays) {
    std::vector<fs::path> files;
    const fs::path root = M3055_SOURCE_DIR;
    for (const char* folder : {"scenes", "tests/data", "assignments"})
        for (const auto& entry : fs::recursive_directory_iterator(root / folder))
            if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path());
    int translucent_scenes = 0;
    for (const fs::path& file : files) {
        Scene scene;
        try {
            scene = load_scene_file(file.string(), LoadContext::trusted());
        } catch (const std::exception&) {
            continue;  // not a scene (an assignment's rules, a deliberately bad file)
        }
        if (!has_translucent(scene)) continue;
        ++translucent_scenes;
        EXPECT_EQ(compare_blends(scene), "") << file;
    }
    // Fig. 7, 8, 9, the gallery, the reference image's translucent_over_opaque at least.
    EXPECT_GE(translucent_scenes, 5);
}

TEST(TranslucentBlend, OverlappingTranslucentSpheresInOneDraw) {
    std::vector<Object> stack;
    for (int i = 0; i < 6; ++i)
        stack.push_back(sphere({-0.9 + 0.35 * i, 0.1 * i, 0.4 + 0.25 * i}, 0.5,
                               translucent({0.2 + 0.1 * i, 0.5, 0.9 - 0.1 * i}, 0.3 + 0.1 * i, 1.0)));
    const Scene scene = small_scene(stack);
    EXPECT_EQ(compare_blends(scene), "");
    EXPECT_EQ(compare_blends(scene, ShaderMode::general), "");
    EXPECT_EQ(compare_blends(scene, ShaderMode::specialized, true), "");
}

TEST(TranslucentBlend, HundredsOfNestedSpheresOnOnePixel) {
    // 300 nested spheres around the view axis, all over the centre pixels
    // (more than an 8-bit stencil could count in one draw).
    std::vector<Object> nested;
    for (int i = 0; i < 300; ++i)
        nested.push_back(sphere({0.0, 0.0, 0.5 + 0.005 * i}, 0.3 + 0.001 * (i % 7),
                                translucent({0.9, 0.6, 0.3}, 0.02, 0.5)));
    Scene scene = small_scene(nested);
    scene.display.width = 32, scene.display.height = 20;
    EXPECT_EQ(compare_blends(scene), "");
}

TEST(TranslucentBlend, TorusWithTwoFrontFacesOnOnePixelOverASphere) {
    // Seen obliquely, the far side of the ring lies behind the near side: two
    // front faces on one pixel, in one draw.
    const Scene scene = small_scene({torus({0, 0, 0.6}, {0, 1, 0.35}, 1.0, 0.3, translucent({0.3, 0.8, 0.5}, 0.5, 1.0)),
                                     sphere({0.4, 0.2, 1.6}, 0.3, translucent({0.9, 0.4, 0.2}, 0.6, 1.0))});
    EXPECT_EQ(compare_blends(scene), "");
    EXPECT_EQ(compare_blends(scene, ShaderMode::general, true), "");
}

TEST(TranslucentBlend, TranslucentMeshesAmongSpheresInPerspectiveAndOrthographic) {
    const Object box = cube({-0.8, 0, 0.8}, 0.8, {20, 35, 10}, translucent({0.9, 0.9, 0.3}, 0.4, 1.0));
    const Object tube = cylinder({0.8, 0, 0.6}, {0.3, 1, 0.6}, 0.4, 1.2, false, translucent({0.4, 0.6, 0.9}, 0.5, 0.5));
    Object plane;
    plane.shape = Shape::plane;
    plane.center = {0, -0.2, 1.4}, plane.axis = glm::normalize(dvec3(0, 0.4, 1)), plane.size = 1.5;
    plane.material = translucent({0.8, 0.8, 0.8}, 0.2, 0.0);
    Scene scene = small_scene({box, tube, plane, sphere({0, 0.3, 1.2}, 0.4, translucent({1, 0.3, 0.3}, 0.5, 1))});
    EXPECT_EQ(compare_blends(scene), "");
    scene.camera.projection = Projection::orthographic;
    scene.camera.height = 3.0;
    EXPECT_EQ(compare_blends(scene), "");
}

TEST(TranslucentBlend, DefaultIsDualSourceWhereTheContextHasItUnlessTheEnvironmentSaysNo) {
    const GlApi& gl = test::shared_gl();
    const char* before = std::getenv("M3055_NO_DUAL_SOURCE");
    const std::string saved = before ? before : "";
    unsetenv("M3055_NO_DUAL_SOURCE");
    EXPECT_EQ(default_translucent_blend(gl), TranslucentBlend::dual_source);  // GL 3.3 core has it
    setenv("M3055_NO_DUAL_SOURCE", "0", 1);
    EXPECT_EQ(default_translucent_blend(gl), TranslucentBlend::dual_source);
    setenv("M3055_NO_DUAL_SOURCE", "1", 1);
    EXPECT_EQ(default_translucent_blend(gl), TranslucentBlend::two_pass);
    EXPECT_EQ(Renderer(gl).translucent_blend(), TranslucentBlend::two_pass);
    if (before) setenv("M3055_NO_DUAL_SOURCE", saved.c_str(), 1);
    else unsetenv("M3055_NO_DUAL_SOURCE");
    EXPECT_EQ(gl.GetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace m3055
