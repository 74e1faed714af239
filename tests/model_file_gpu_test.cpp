// Meshes from model files on the GPU: against the CPU reference, which
// ray-casts the same triangles in double through its BVH (tolerances as
// shapes_gpu_test.cpp's); a UV sphere written with exact normals against the
// analytic sphere away from its silhouette; the same mesh as .obj, .gltf
// (embedded and side buffer) and .glb rendering byte-identically; a flat
// cube file against the built-in cube.
#include "gpu_compare.h"
#include "model_writer.h"
#include "object_builders.h"
#include "test_support.h"

#include "frame/renderer.h"
#include "geometry/mesh.h"
#include "reference/reference.h"
#include "scene/load.h"
#include "scene/load_context.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace m3055 {
namespace {

using nlohmann::json;
using test::TempDir;

constexpr double kTolerance = 1e-3;
constexpr double kSameLevelShare = 0.995;

json camera(bool orthographic) {
    json c = {{"projection", orthographic ? "orthographic" : "perspective"},
              {"position", {1.5, 1.2, 5}},
              {"target", {0, 0, 0}},
              {"up", {0, 1, 0}}};
    if (orthographic) c["height"] = 3.0;
    else c["fov_y_deg"] = 35;
    return c;
}

// A scene of `objects` at 256 x 160, a key and a fill light.
Scene scene_of(const TempDir& dir, const json& objects, bool orthographic = false) {
    const json doc = {{"display", {{"width", 256}, {"height", 160}, {"bits", 5}}},
                      {"camera", camera(orthographic)},
                      {"lights",
                       {{{"type", "directional"}, {"direction", {1, 1, 1}}, {"intensity", 0.8}},
                        {{"type", "point"}, {"position", {-3, 1, 4}}, {"intensity", 0.4}}}},
                      {"objects", objects}};
    test::write_text(dir.file("scene.json"), doc.dump());
    return load_scene_file(dir.file("scene.json"), LoadContext::trusted());
}

json mesh_object(const std::string& file, const json& center, double size, const json& rotation) {
    return {{"shape", "mesh"}, {"file", file}, {"center", center}, {"size", size}, {"rotation_deg", rotation}};
}

json highlight(const json& color) { return {{"model", "highlight"}, {"color", color}, {"d", 0.5}, {"w", 1.0}, {"m", 12}}; }

void expect_matches(const Scene& scene) {
    const test::Comparison result = test::compare_gpu_with_reference(scene);
    SCOPED_TRACE(result.describe());
    EXPECT_GT(result.interior_pixels, 2000);
    EXPECT_EQ(result.nonfinite_values, 0);
    EXPECT_LE(result.max_scaled_diff, kTolerance);
    EXPECT_GE(result.same_level_share, kSameLevelShare);
    EXPECT_LE(result.max_level_diff, 1);
}

class ModelFileGpu : public ::testing::TestWithParam<bool> {};

// A two-material OBJ (phong from its .mtl, no normals: the loader's own) and
// a principled glTF sphere side by side, against the reference.
TEST_P(ModelFileGpu, FileMaterialsMatchTheReference) {
    TempDir dir;
    geometry::Mesh torus = geometry::make_torus(dvec3(0.0), dvec3(0, 1, 0.4), 1.0, 0.35, 48);
    torus.groups.assign(torus.triangles(), 0);
    for (std::size_t t = torus.triangles() / 2; t < torus.triangles(); ++t) torus.groups[t] = 1;
    test::write_obj(torus, dir.file("torus.obj"), false, "torus.mtl");
    test::write_text(dir.file("torus.mtl"), "newmtl m0\nKd 0.6 0.3 0.1\nKs 0.3 0.3 0.3\nNs 30\n"
                                            "newmtl m1\nKd 0.1 0.3 0.6\nKs 0.5 0.5 0.5\nNs 200\n");
    test::write_glb(test::integer_uv_sphere(64, 32, 1000, 1000), dir.file("ball.glb"));
    const Scene scene = scene_of(dir,
                                 {mesh_object("torus.obj", {-0.9, 0, 0}, 2.2, {20, 0, 0}),
                                  mesh_object("ball.glb", {1.3, 0, -0.5}, 1.6, {0, 0, 0})},
                                 GetParam());
    ASSERT_EQ(scene.objects[0].groups.size(), 2u);
    EXPECT_EQ(scene.objects[1].groups[0].material.model_name(), "principled");
    expect_matches(scene);
}

INSTANTIATE_TEST_SUITE_P(Projection, ModelFileGpu, ::testing::Bool(),
                         [](const auto& info) { return std::string(info.param ? "ortho" : "persp"); });

// A glTF sheet (one quad facing +z) seen from behind: culled as a one-sided
// surface, as the spec shades only front faces; with its material doubleSided
// (glTF 2.0 §3.9.6) its back is drawn, lit with the normal reversed, on the
// GPU as in the reference. Front and back of a lit double-sided sheet are the
// same quad lit from either side.
TEST(ModelFileAccuracy, ADoubleSidedGltfMaterialShowsItsBack) {
    TempDir dir;
    geometry::Mesh sheet;
    sheet.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    sheet.normals.assign(4, dvec3(0, 0, 1));
    sheet.indices = {0, 1, 2, 0, 2, 3};
    sheet.parts = {0, 0};
    auto lit_pixels = [](const Rgb8Image& image) {
        long lit = 0;
        for (std::uint8_t v : image.pixels) lit += v != 0;
        return lit;
    };
    Renderer& renderer = test::shared_renderer();
    for (const bool double_sided : {false, true}) {
        SCOPED_TRACE(double_sided ? "doubleSided" : "one-sided");
        test::write_gltf(sheet, dir.file("sheet.gltf"));
        json doc = json::parse(test::read_text(dir.file("sheet.gltf")));
        doc["materials"] = json::array({{{"name", "paper"}, {"doubleSided", double_sided},
                                         {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.7, 0.5, 1}},
                                                                   {"metallicFactor", 0.0}, {"roughnessFactor", 0.6}}}}});
        doc["meshes"][0]["primitives"][0]["material"] = 0;
        test::write_text(dir.file("sheet.gltf"), doc.dump());
        // Turned 160 degrees about y: the camera (at +z) sees its back; the key light is behind the camera.
        const Scene scene = scene_of(dir, json::array({mesh_object("sheet.gltf", {0, 0, 0}, 2.5, {0, 160, 0})}));
        renderer.render(scene);
        const long lit = lit_pixels(renderer.read_display());
        if (!double_sided) {
            EXPECT_EQ(lit, 0);
            continue;
        }
        EXPECT_GT(lit, 10000);
        expect_matches(scene);
    }
}

// Pixels whose 3 x 3 neighbourhood is covered in both coverages.
bool interior(const ref::ReferenceImage& a, const ref::ReferenceImage& b, int x, int y, int w, int h) {
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int u = x + dx, v = y + dy;
            if (u < 0 || v < 0 || u >= w || v >= h) return false;
            if (!a.coverage[std::size_t(v * w + u)] || !b.coverage[std::size_t(v * w + u)]) return false;
        }
    return true;
}

TEST(ModelFileAccuracy, UvSphereWithExactNormalsMatchesTheAnalyticSphere) {
    TempDir dir;
    // Radius 100 000 in whole numbers, normals the exact direction to each
    // (rounded) vertex, scaled by 10^6: within 10^-5 of the sphere.
    test::write_obj(test::integer_uv_sphere(256, 128, 100000, 1e6), dir.file("ball.obj"));
    const json material = highlight({0.8, 0.5, 0.2});
    json file_object = mesh_object("ball.obj", {0, 0, 0}, 2.0, {0, 0, 0});
    file_object["material"] = material;
    const Scene mesh_scene = scene_of(dir, json::array({file_object}));
    const Scene sphere_scene =
        scene_of(dir, json::array({{{"shape", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1.0}, {"material", material}}}));
    Renderer& renderer = test::shared_renderer();
    renderer.render(mesh_scene);
    const Rgb8Image mesh_image = renderer.read_display();
    renderer.render(sphere_scene);
    const Rgb8Image sphere_image = renderer.read_display();
    const ref::ReferenceImage a = ref::render_reference(mesh_scene), b = ref::render_reference(sphere_scene);
    const int w = mesh_image.width, h = mesh_image.height;
    long compared = 0, same = 0;
    int worst = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!interior(a, b, x, y, w, h)) continue;  // both rows top to bottom
            ++compared;
            bool all_same = true;
            for (int c = 0; c < 3; ++c) {
                const std::size_t i = std::size_t((y * w + x) * 3 + c);
                const int d = std::abs(int(mesh_image.pixels[i]) - int(sphere_image.pixels[i]));
                worst = std::max(worst, d);
                all_same = all_same && d == 0;
            }
            same += all_same;
        }
    ASSERT_GT(compared, 5000);
    EXPECT_GE(double(same) / double(compared), 0.99) << same << " of " << compared;
    std::printf("UV sphere against the analytic sphere: %ld of %ld interior pixels the same, worst %d PNG values\n",
                same, compared, worst);
    EXPECT_LE(worst, 9) << "more than one 5-bit level (8 or 9 PNG values) apart";
}

TEST(ModelFileAccuracy, TheSameMeshAsObjGltfAndGlbRendersByteIdentically) {
    TempDir dir;
    const geometry::Mesh ball = test::integer_uv_sphere(48, 24, 1000, 1000);
    test::write_obj(ball, dir.file("ball.obj"));
    test::write_gltf(ball, dir.file("embedded.gltf"), test::GltfBuffer::embedded);
    test::write_gltf(ball, dir.file("side.gltf"), test::GltfBuffer::side_file);
    test::write_glb(ball, dir.file("ball.glb"));
    Renderer& renderer = test::shared_renderer();
    std::vector<Rgb8Image> displays;
    std::vector<RgbFloatImage> raws;
    for (const std::string file : {"ball.obj", "embedded.gltf", "side.gltf", "ball.glb"}) {
        json object = mesh_object(file, {0.2, 0, 0}, 2.2, {10, 30, 0});
        object["material"] = highlight({0.3, 0.6, 0.9});
        renderer.render(scene_of(dir, json::array({object})));
        displays.push_back(renderer.read_display());
        raws.push_back(renderer.read_raw());
    }
    long lit = 0;
    for (std::uint8_t v : displays[0].pixels) lit += v != 0;
    EXPECT_GT(lit, 3000);
    for (std::size_t i = 1; i < displays.size(); ++i) {
        EXPECT_EQ(displays[i].pixels, displays[0].pixels) << i;
        EXPECT_EQ(raws[i].pixels, raws[0].pixels) << i;
    }
}

// A model of two materials (the vase's glaze and rim) dressed whole by "material"
// draws every face of either in that material: the same bytes as the model
// with each of its materials overridden to it, render after render (under a
// shadowed rect key, where a wrong group's faces went missing in some renders).
TEST(ModelFileAccuracy, AModelDressedWholeByMaterialDrawsEveryGroupInIt) {
    TempDir dir;
    for (const char* file : {"vase.obj", "vase.mtl"})
        test::write_text(dir.file(file), test::read_text(test::source_path(std::string("scenes/models/") + file)));
    const json glaze = highlight({0.55, 0.25, 0.12});
    json whole = mesh_object("vase.obj", {0, 0, 0}, 2.4, {0, 0, 0});
    whole["material"] = glaze;
    json by_name = mesh_object("vase.obj", {0, 0, 0}, 2.4, {0, 0, 0});
    by_name["materials"] = {{"glaze", glaze}, {"rim", glaze}};
    const auto render = [&](const json& object) {
        const json doc = {{"display", {{"width", 128}, {"height", 80}, {"bits", 5}}},
                          {"camera", camera(false)},
                          {"lights",
                           {{{"type", "rect"}, {"position", {2, 3, 2}}, {"normal", {-2, -3, -2}}, {"size", {1, 1}},
                             {"intensity", 6}, {"shadow", true}}}},
                          {"objects", json::array({object})}};
        test::write_text(dir.file("scene.json"), doc.dump());
        Renderer& renderer = test::shared_renderer();
        renderer.render(load_scene_file(dir.file("scene.json"), LoadContext::trusted()));
        return renderer.read_display().pixels;
    };
    const auto expected = render(by_name);
    for (int i = 0; i < 2; ++i) EXPECT_EQ(render(whole), expected) << "render " << i;
}

TEST(ModelFileAccuracy, AFlatCubeFileEqualsTheBuiltInCube) {
    TempDir dir;
    // The built-in cube's own triangles and face normals, at size 2 around the origin (whole numbers).
    test::write_obj(geometry::make_cube(dvec3(0.0), 2.0, dvec3(0.0)), dir.file("cube.obj"));
    const json material = highlight({0.9, 0.7, 0.3});
    json file_object = mesh_object("cube.obj", {0.3, -0.2, 0}, 1.7, {25, 40, 10});
    file_object["material"] = material;
    const json cube_object = {{"shape", "cube"}, {"center", {0.3, -0.2, 0}}, {"size", 1.7},
                              {"rotation_deg", {25, 40, 10}}, {"material", material}};
    Renderer& renderer = test::shared_renderer();
    renderer.render(scene_of(dir, json::array({file_object})));
    const Rgb8Image file_image = renderer.read_display();
    renderer.render(scene_of(dir, json::array({cube_object})));
    const Rgb8Image cube_image = renderer.read_display();
    long lit = 0;
    for (std::uint8_t v : cube_image.pixels) lit += v != 0;
    EXPECT_GT(lit, 3000);
    EXPECT_EQ(file_image.pixels, cube_image.pixels);
}

}  // namespace
}  // namespace m3055
