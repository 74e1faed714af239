// m3055 brdf-check (app/cmd_brdf_check.cpp) and the GPU grid it measures
// (passes/brdf_grid.h): the grid is the CPU reference's BRDF for the built-in
// models; deliberately broken .brdf files fail and correct ones pass; every
// built-in model is classified as docs/models.md says.
#include "analysis/brdf_check.h"
#include "brdf_file/brdf_model.h"
#include "gl/context.h"
#include "models/model_table.h"
#include "passes/brdf_grid.h"
#include "reference/reference.h"
#include "material_support.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace m3055 {
namespace {

std::string data_file(const std::string& name) { return test::source_path("tests/data/brdf/" + name); }

TEST(BrdfGrid, GpuIsTheCpuReferenceBrdfForBuiltInModels) {
    const auto context = HeadlessContext::create(Backend::automatic);
    BrdfGrid grid(context->gl());
    const std::vector<dvec3> dirs = check_directions(6, 8);
    for (const std::string& name : test::builtin_models_of(Family::classic)) {
        const Material material = Material::of(name);
        const std::vector<float> f = grid.evaluate(material, dirs, dirs);
        Light light;
        light.type = LightType::directional;
        double worst = 0;
        for (std::size_t j = 0; j < dirs.size(); ++j)
            for (std::size_t i = 0; i < dirs.size(); ++i) {
                if (!(dirs[i].z > 1e-3 && dirs[j].z > 1e-3)) continue;
                light.direction = dirs[i];
                const dvec3 I = ref::shade_opaque(material, {light}, {dvec3(0.0), dvec3(0, 0, 1), dirs[j]}, dvec3(0.0));
                for (int c = 0; c < 3; ++c) {
                    const double expected = I[c] / (3.14159265358979323846 * dirs[i].z);
                    const double diff = std::abs(f[(j * dirs.size() + i) * 3 + std::size_t(c)] - expected);
                    worst = std::max(worst, diff / std::max(1.0, std::abs(expected)));
                }
            }
        EXPECT_LE(worst, 1e-3) << name;
    }
}

// The explorer's edit loop (renderer side): a reload that breaks the GLSL is
// reported with the .brdf's line and the last good material still compiles.
TEST(BrdfGrid, ACompileErrorNamesTheFilesLineAndTheLastGoodMaterialStays) {
    const auto context = HeadlessContext::create(Backend::automatic);
    test::TempDir dir;
    const std::string path = dir.file("live.brdf");
    const std::string head = "analytic\n::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\n";
    test::write_text(path, head + "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec3(k); }\n::end shader\n");
    const Material good = reload_brdf_material(Material::of("lambert"), path);
    EXPECT_EQ(brdf_compile_error(context->gl(), good), "");
    test::write_text(path, head + "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {\n    return vec3(k) + kk;\n}\n"
                                  "::end shader\n");
    const Material broken = reload_brdf_material(good, path);
    EXPECT_EQ(brdf_compile_error(context->gl(), broken), path + ":7: error: `kk' undeclared");
    EXPECT_EQ(brdf_compile_error(context->gl(), good), "");
}

TEST(BrdfCheck, ASqrtOfANegativeFails) {
    const test::RunResult r = test::run_m3055({"brdf-check", data_file("broken_sqrt.brdf")});
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("| FAIL | "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("NaN/Inf"), std::string::npos) << r.out;
}

TEST(BrdfCheck, AMissingOneOverPiIsAnEnergyGainOfPi) {
    const test::RunResult plain = test::run_m3055({"brdf-check", data_file("broken_no_pi.brdf")});
    EXPECT_EQ(plain.exit_code, 0) << plain.out << plain.err;  // finite and positive: only the albedo is wrong
    EXPECT_NE(plain.out.find("| GAIN x3.14 | 3.14"), std::string::npos) << plain.out;
    const test::RunResult strict =
        test::run_m3055({"brdf-check", data_file("broken_no_pi.brdf"), "--require-conserving"});
    EXPECT_EQ(strict.exit_code, 1) << strict.out;
}

TEST(BrdfCheck, CorrectFilesPass) {
    for (const auto& args : std::vector<std::vector<std::string>>{
             {"brdf-check", data_file("lambert.brdf"), "--require-conserving"},
             {"brdf-check", data_file("ggx_schlick.brdf"), "--set", "kd=[0,0,0]", "--require-conserving"},
             {"brdf-check", data_file("blinn_phong.brdf"), "--set", "shininess=32"}}) {
        const test::RunResult r = test::run_m3055(args);
        EXPECT_EQ(r.exit_code, 0) << args[1] << "\n" << r.out << r.err;
        EXPECT_NE(r.out.find("| PASS | 0 NaN/Inf, 0 negative"), std::string::npos) << r.out;
    }
}

// docs/models.md: reciprocal or not, as the classic models' tests say; the
// microfacet model's D normalized and, with F = 1 and no diffuse, <= 1.
TEST(BrdfCheck, EveryBuiltInModelAsTheDocsSay) {
    const std::set<std::string> not_reciprocal = {"highlight", "metal_blinn", "metal_phong", "half_lambert",
                                                  "half_lambert_clamped", "half_lambert_normalized", "phong",
                                                  "blinn_phong", "heidrich_seidel"};
    for (const ModelSpec& spec : model_table().models()) {
        if (spec.family == Family::brdf) continue;
        const test::RunResult r = test::run_m3055({"brdf-check", spec.name});
        if (spec.family == Family::translucent) {
            EXPECT_EQ(r.err, "m3055: translucent: a translucent model is not a BRDF\n");
            continue;
        }
        EXPECT_EQ(r.exit_code, 0) << spec.name << r.out << r.err;
        const bool reciprocal = r.out.find("| reciprocal |") != std::string::npos;
        EXPECT_EQ(reciprocal, !not_reciprocal.count(spec.name)) << spec.name << "\n" << r.out;
    }
    const test::RunResult furnace =
        test::run_m3055({"brdf-check", "microfacet", "--set", "kd=[0,0,0]", "--set", "fresnel=none", "--require-conserving"});
    EXPECT_EQ(furnace.exit_code, 0) << furnace.out;
    EXPECT_NE(furnace.out.find("| normalized | 1.000000"), std::string::npos) << furnace.out;
}

TEST(BrdfCheck, BadTargetsAreOneLine) {
    EXPECT_EQ(test::run_m3055({"brdf-check", "plastic"}).err, "m3055: no model named \"plastic\" (nor a .brdf file)\n");
    EXPECT_EQ(test::run_m3055({"brdf-check", "lambert", "--set", "shininess=3"}).err,
              "m3055: --set shininess: not a parameter of Lambert\n");
    const test::RunResult range = test::run_m3055({"brdf-check", "phong", "--set", "shininess=-1"});
    EXPECT_EQ(range.exit_code, 1);
    EXPECT_NE(range.err.find("--set shininess: must be a number"), std::string::npos) << range.err;
}

}  // namespace
}  // namespace m3055
