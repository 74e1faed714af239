// .brdf files as models (renderer/brdf_file/brdf_model.h, scene/json_brdf.h):
// the project's own Lambert, Blinn-Phong and GGX + Schlick files render as the
// built-in models they copy, within the GPU tolerances of docs/models.md;
// scenes name them with errors naming the scene, the JSON path and the .brdf.
#include "brdf_file/brdf_model.h"
#include "gl/context.h"
#include "gpu_compare.h"
#include "models/glsl_generator.h"
#include "models/model_table.h"
#include "frame/renderer.h"
#include "scene/presets.h"
#include "models/model_spec.h"
#include "reference/reference.h"
#include "scene/load.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace m3055 {
namespace {

using nlohmann::json;

std::string data_file(const std::string& name) { return test::source_path("tests/data/brdf/" + name); }

// A material from `file` with `values` set by the file's parameter names.
Material brdf_material(const std::string& file, const std::vector<std::pair<std::string, double>>& numbers,
                       const std::vector<std::pair<std::string, dvec3>>& colours) {
    const BrdfModel& model = load_brdf_model(data_file(file));
    Material m(*model.spec);
    for (const auto& [name, value] : numbers) m.set_number(model.field(name), value);
    for (const auto& [name, value] : colours) m.set_vec3(model.field(name), value);
    return m;
}

std::vector<std::vector<Light>> light_setups() {
    Light point;
    point.type = LightType::point;
    point.position = {-2, 1.5, 3};
    point.att_constant = 0.5, point.att_linear = 0.1, point.att_quadratic = 0.02;
    point.color = {0.9, 0.8, 0.6};
    Light spot;
    spot.type = LightType::spot;
    spot.position = {0.5, 3, 3};
    spot.spot_direction = glm::normalize(dvec3(-0.5, -3, -3));
    spot.spot_exponent = 8;
    return {{test::directional({1, 1, 1})},
            {test::directional({1, 1, 1}), test::directional({-1, 0.2, 0.5}, 0.4, {0.3, 0.5, 1.0}), point, spot},
            {test::directional({0, 0, -1})},                  // behind: nothing
            {test::directional({1, 0, 0.02}, 2.0)}};          // grazing
}

// Every light set-up, both cameras, specialized and general programs; prints
// the worst case measured (docs/brdf-files.md quotes it).
void expect_same_as(const Material& from_file, const Material& builtin, const std::string& what) {
    double worst_scaled = 0, fewest_same = 1;
    for (const auto& lights : light_setups())
        for (bool ortho : {false, true})
            for (ShaderMode mode : {ShaderMode::specialized, ShaderMode::general}) {
                const test::Comparison c = test::compare_gpu_with_reference_of(
                    test::single_sphere_scene(from_file, lights, ortho),
                    test::single_sphere_scene(builtin, lights, ortho), mode);
                SCOPED_TRACE(what + (ortho ? " ortho" : " persp") + " lights " + std::to_string(lights.size()) +
                             ": " + c.describe());
                EXPECT_GT(c.interior_pixels, 1000);
                EXPECT_EQ(c.nonfinite_values, 0);
                EXPECT_LE(c.max_scaled_diff, 1e-3);
                EXPECT_GE(c.same_level_share, 0.995);
                EXPECT_LE(c.max_level_diff, 1);
                worst_scaled = std::max(worst_scaled, c.max_scaled_diff);
                fewest_same = std::min(fewest_same, c.same_level_share);
            }
    std::printf("%s: worst scaled diff %.2g, fewest on the same level %.4f %%\n", what.c_str(), worst_scaled,
                100 * fewest_same);
}

TEST(BrdfModel, LambertFileIsTheBuiltInLambert) {
    Material builtin = Material::of("lambert");
    builtin.set_vec3("kd", {0.7, 0.3, 0.2});
    expect_same_as(brdf_material("lambert.brdf", {}, {{"kd", {0.7, 0.3, 0.2}}}), builtin, "lambert");
}

TEST(BrdfModel, BlinnPhongFileIsTheBuiltInBlinnPhong) {
    for (double n : {1.0, 32.0, 200.0}) {
        Material builtin = Material::of("blinn_phong");
        builtin.set_vec3("kd", {0.7, 0.3, 0.2});
        builtin.set_vec3("ks", {0.9, 0.9, 0.8});
        builtin.set_number("shininess", n);
        expect_same_as(brdf_material("blinn_phong.brdf", {{"shininess", n}}, {{"kd", {0.7, 0.3, 0.2}}, {"ks", {0.9, 0.9, 0.8}}}),
                       builtin, "blinn_phong n " + std::to_string(n));
    }
}

TEST(BrdfModel, GgxSchlickFileIsTheBuiltInMicrofacet) {
    for (double m : {0.1, 0.3, 0.8})
        for (double ior : {1.5, 3.0}) {
            Material builtin = Material::of("microfacet");
            builtin.set_vec3("kd", {0.2, 0.5, 0.3});
            builtin.set_choice("distribution", "ggx");
            builtin.set_choice("fresnel", "schlick");
            builtin.set_number("ior", ior);
            builtin.set_lobes({{1.0, m}});
            expect_same_as(brdf_material("ggx_schlick.brdf", {{"m", m}, {"ior", ior}}, {{"kd", {0.2, 0.5, 0.3}}}),
                           builtin, "ggx m " + std::to_string(m) + " ior " + std::to_string(ior));
        }
}

TEST(BrdfModel, AnUnchangedFileIsOneEntryAndTheDefaultsAreTheFiles) {
    const BrdfModel& a = load_brdf_model(data_file("ggx_schlick.brdf"));
    const BrdfModel& b = load_brdf_model(data_file("ggx_schlick.brdf"));
    EXPECT_EQ(a.spec, b.spec);
    EXPECT_EQ(a.spec->family, Family::brdf);
    const Material m(*a.spec);
    EXPECT_EQ(m.number(a.field("m")), 0.3);
    EXPECT_EQ(m.number(a.field("ior")), 1.5);
    EXPECT_EQ(m.vec3(a.field("kd")), dvec3(0.2, 0.5, 0.3));
    EXPECT_EQ(m.vec3("axis"), dvec3(0, 1, 0));
    EXPECT_EQ(a.spec->param(a.field("m")).range.lo, 0.001);
}

TEST(BrdfModel, ReloadKeepsTheValuesOfUnchangedParameters) {
    test::TempDir dir;
    const std::string path = dir.file("x.brdf");
    const std::string shader = "::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec3(a); }\n::end shader\n";
    test::write_text(path, "analytic\n::begin parameters\nfloat a 0 1 0.5\nfloat b 0 1 0.5\n::end parameters\n" + shader);
    const BrdfModel& first = load_brdf_model(path);
    Material current(*first.spec);
    current.set_number(first.field("a"), 0.9);
    current.set_number(first.field("b"), 0.8);
    current.set_vec3("axis", {1, 0, 0});
    test::write_text(path, "analytic\n::begin parameters\nfloat a 0 0.7 0.1\ncolor b 1 1 1\nbool c 1\n::end parameters\n" +
                               shader);
    const Material reloaded = reload_brdf_material(current, path);
    const BrdfModel* second = find_brdf_model(reloaded.model());
    ASSERT_NE(second, nullptr);
    EXPECT_NE(second->spec, first.spec);
    EXPECT_EQ(reloaded.number(second->field("a")), 0.7);          // kept, clamped into the new range
    EXPECT_EQ(reloaded.vec3(second->field("b")), dvec3(1, 1, 1));  // kind changed: the file's default
    EXPECT_TRUE(reloaded.flag(second->field("c")));
    EXPECT_EQ(reloaded.vec3("axis"), dvec3(1, 0, 0));
    test::write_text(path, "analytic\n::begin parameters\nfloat a 0 1\n::end parameters\n" + shader);
    try {
        reload_brdf_material(reloaded, path);
        ADD_FAILURE() << "a broken file reloaded";
    } catch (const BrdfError& e) {
        EXPECT_NE(std::string(e.what()).find("x.brdf:3: \"float\" needs 4 fields after it, got 3"), std::string::npos)
            << e.what();
    }
}

// ---- scenes -------------------------------------------------------------------------

json scene_with(const json& material) {
    return {{"camera", {{"projection", "orthographic"}, {"height", 2.5}, {"position", {0, 0, 4}}, {"target", {0, 0, 0}}}},
            {"lights", json::array({{{"type", "directional"}, {"direction", {1, 1, 1}}}})},
            {"objects", json::array({{{"shape", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}, {"material", material}}})}};
}

std::string load_error(const test::TempDir& dir, const json& material) {
    test::write_text(dir.file("s.json"), scene_with(material).dump());
    try {
        load_scene_file(dir.file("s.json"), LoadContext::trusted());
    } catch (const SceneError& e) {
        return e.what();
    }
    return std::string();
}

TEST(BrdfScene, FileIsRelativeToTheSceneAndParamsDefaultToTheFiles) {
    test::TempDir dir;
    test::write_text(dir.file("g.brdf"), test::read_text(data_file("ggx_schlick.brdf")));
    test::write_text(dir.file("s.json"),
                     scene_with({{"model", "brdf"}, {"file", "g.brdf"}, {"params", {{"m", 0.2}}}}).dump());
    const Scene scene = load_scene_file(dir.file("s.json"), LoadContext::trusted());
    const Material& m = scene.objects.at(0).material;
    const BrdfModel* model = find_brdf_model(m.model());
    ASSERT_NE(model, nullptr);
    EXPECT_EQ(m.number(model->field("m")), 0.2);
    EXPECT_EQ(m.number(model->field("ior")), 1.5);
    // Written back: the same material again.
    const Scene again =
        scene_from_json(scene_to_json(scene, PathWriting::absolute()), "again.json", LoadContext::trusted());
    EXPECT_EQ(again.objects.at(0).material, m);
}

TEST(BrdfScene, ErrorsNameTheSceneThePathAndTheBrdf) {
    test::TempDir dir;
    test::write_text(dir.file("g.brdf"), test::read_text(data_file("ggx_schlick.brdf")));
    const std::string s = dir.file("s.json");
    const std::string at = s + ": objects[0].material.";
    EXPECT_EQ(load_error(dir, {{"model", "brdf"}, {"file", "g.brdf"}, {"params", {{"rough", 0.2}}}}),
              at + "params.rough: not a parameter of " + dir.file("g.brdf"));
    EXPECT_EQ(load_error(dir, {{"model", "brdf"}, {"file", "g.brdf"}, {"params", {{"m", 3}}}}),
              at + "params.m: must be in [0.001, 2], got 3 (" + dir.file("g.brdf") + ")");
    EXPECT_EQ(load_error(dir, {{"model", "brdf"}, {"file", "g.brdf"}, {"params", {{"kd", 0.5}}}}),
              at + "params.kd: must be an array of 3 numbers (" + dir.file("g.brdf") + ")");
    EXPECT_EQ(load_error(dir, {{"model", "brdf"}, {"file", "none.brdf"}}).rfind(at + "file: " + dir.file("none.brdf"), 0),
              0u);
    EXPECT_EQ(load_error(dir, {{"model", "brdf"}}), at + "file: is required");
    EXPECT_EQ(load_error(dir, {{"model", "brdf"}, {"file", "g.brdf"}, {"kd", {1, 1, 1}}}), at + "kd: unknown key");
    test::write_text(dir.file("bad.brdf"), "analytic\n::begin parameters\nfloat float 0 1 0\n::end parameters\n");
    EXPECT_EQ(load_error(dir, {{"model", "brdf"}, {"file", "bad.brdf"}}),
              at + "file: " + dir.file("bad.brdf") +
                  ":3: parameter name \"float\" is a GLSL keyword or built-in, or a name the renderer uses");
}

// ---- the command line ------------------------------------------------------------------

TEST(BrdfCli, GlslErrorNamesTheBrdfLine) {
    test::TempDir dir;
    test::write_text(dir.file("bad.brdf"), "analytic\n# line 2\n::begin parameters\nfloat k 0 1 0.5\n::end parameters\n"
                                           "::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)\n{\n"
                                           "    return vec3(k) * undefined_thing;\n}\n::end shader\n");
    test::write_text(dir.file("s.json"), scene_with({{"model", "brdf"}, {"file", "bad.brdf"}}).dump());
    const test::RunResult r = test::run_m3055({"render", "--scene", dir.file("s.json"), "--out", dir.file("o.png")});
    EXPECT_EQ(r.exit_code, 1);
    // One line, the .brdf's own line 9, the author's names (not the renamed ones).
    EXPECT_EQ(r.err, "m3055: " + dir.file("bad.brdf") + ":9: error: `undefined_thing' undeclared\n");
    EXPECT_FALSE(std::filesystem::exists(dir.file("o.png")));
}

TEST(BrdfCli, RenderAcceptsTheFileAndBatchOnlyWithAllowBrdf) {
    test::TempDir dir;
    test::write_text(dir.file("g.brdf"), test::read_text(data_file("ggx_schlick.brdf")));
    test::write_text(dir.file("s.json"), scene_with({{"model", "brdf"}, {"file", "g.brdf"}}).dump());
    const test::RunResult render = test::run_m3055({"render", "--scene", dir.file("s.json"), "--out", dir.file("r.png")});
    ASSERT_EQ(render.exit_code, 0) << render.err;
    test::write_text(dir.file("m.json"), R"([{"scene": "s.json", "out": "b.png"}])");
    const test::RunResult refused = test::run_m3055({"batch", dir.file("m.json")});
    EXPECT_EQ(refused.exit_code, 1);
    EXPECT_NE(refused.err.find("objects[0].material.file: a .brdf file is code: m3055 batch and grade run it only with "
                               "--allow-brdf"),
              std::string::npos)
        << refused.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("b.png")));
    const test::RunResult allowed = test::run_m3055({"batch", "--allow-brdf", dir.file("m.json")});
    ASSERT_EQ(allowed.exit_code, 0) << allowed.err;
    EXPECT_EQ(test::read_text(dir.file("b.png")), test::read_text(dir.file("r.png")));
}

}  // namespace
}  // namespace m3055

namespace m3055 {
namespace {

TEST(BrdfCli, FiguresRendersAFolderWithABrdfScene) {
    test::TempDir dir;
    std::filesystem::create_directories(dir.file("scenes"));
    test::write_text(dir.file("scenes/lambert.brdf"), test::read_text(data_file("lambert.brdf")));
    test::write_text(dir.file("scenes/fig_brdf.json"), scene_with({{"model", "brdf"}, {"file", "lambert.brdf"}}).dump());
    const test::RunResult r = test::run_m3055({"figures", "--scenes", dir.file("scenes"), "--out", dir.file("out")});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir.file("out/fig_brdf.png")));
}

}  // namespace
}  // namespace m3055

namespace m3055 {
namespace {

// Three files that all declare PI (and the renderer has its own) in one
// program, one of them twice with different values: each file's names are its own.
TEST(BrdfCli, SeveralFilesWithTheSameNamesInOneScene) {
    test::TempDir dir;
    for (const char* f : {"lambert.brdf", "blinn_phong.brdf", "ggx_schlick.brdf"})
        test::write_text(dir.file(f), test::read_text(data_file(f)));
    json scene = scene_with({{"model", "brdf"}, {"file", "lambert.brdf"}});
    json& objects = scene["objects"];
    const auto sphere = [](double x, const json& material) {
        return json{{"shape", "sphere"}, {"center", {x, 0, 0}}, {"radius", 0.4}, {"material", material}};
    };
    objects = json::array({sphere(-0.9, {{"model", "brdf"}, {"file", "lambert.brdf"}}),
                           sphere(0.0, {{"model", "brdf"}, {"file", "blinn_phong.brdf"}}),
                           sphere(0.9, {{"model", "brdf"}, {"file", "ggx_schlick.brdf"}, {"params", {{"m", 0.1}}}}),
                           sphere(0.0, {{"model", "brdf"}, {"file", "ggx_schlick.brdf"}, {"params", {{"m", 0.6}}}})});
    objects[3]["center"] = {0, 0.9, 0};
    test::write_text(dir.file("s.json"), scene.dump());
    const test::RunResult r = test::run_m3055({"render", "--scene", dir.file("s.json"), "--out", dir.file("s.png")});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir.file("s.png")));
}

}  // namespace
}  // namespace m3055

namespace m3055 {
namespace {

// No C++ twin: the reference says NaN (its callers skip it) rather than throw.
TEST(BrdfModel, CpuReferenceIsNanNotAnException) {
    const Material m(*load_brdf_model(data_file("lambert.brdf")).spec);
    const dvec3 I = ref::shade_opaque(m, {test::directional({0, 0, 1})}, {dvec3(0.0), dvec3(0, 0, 1), dvec3(0, 0, 1)});
    EXPECT_TRUE(std::isnan(I.x) && std::isnan(I.y) && std::isnan(I.z));
}

// A file saved with a GLSL error is an entry of the table like any other (the
// explorer parsed it before compiling); retired, it leaves the general
// programs, so the renderer's general mode draws the other models again.
TEST(BrdfModel, ARetiredBrokenEntryLeavesTheGeneralPrograms) {
    test::TempDir dir;
    test::write_text(dir.file("bad.brdf"), "analytic\n::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)"
                                           " { return vec3(undefined_thing); }\n::end shader\n");
    const BrdfModel& bad = load_brdf_model(dir.file("bad.brdf"));
    const auto context = HeadlessContext::create(Backend::automatic);
    Renderer renderer(context->gl());
    EXPECT_THROW(renderer.warm_up_general_programs(), std::exception) << "the broken code is in the general program";
    const std::vector<std::string> before = every_model_define(model_table());
    EXPECT_NE(std::find(before.begin(), before.end(), has_define(*bad.spec)), before.end());
    retire_brdf_model(*bad.spec);
    const std::vector<std::string> after = every_model_define(model_table());
    EXPECT_EQ(std::find(after.begin(), after.end(), has_define(*bad.spec)), after.end());
    EXPECT_NO_THROW(renderer.warm_up_general_programs());
    retire_brdf_model(Material::of("lambert").model());  // a built-in model is never retired
    EXPECT_FALSE(model_table().retired(Material::of("lambert").model()));
}

}  // namespace
}  // namespace m3055
