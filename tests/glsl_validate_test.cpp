// Every shader program the renderer builds, composed from glsl/ exactly as
// renderer.cpp composes it, must pass the Khronos reference compiler
// (glslangValidator): a shader that only llvmpipe accepts would break on
// stricter drivers. A missing glslangValidator is a failure, not a skip.
#include "gl/shader_source.h"
#include "models/model_table.h"
#include "passes/light_uniforms.h"
#include "passes/shader_plan.h"
#include "passes/translucent_blend.h"
#include "scene/load.h"
#include "glslang_tool.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <sstream>
#include <ostream>
#include <string>
#include <vector>

namespace m3055 {
namespace {

using test::TempDir;
using test::ToolRun;
using test::run_glslang;

// One program as renderer.cpp asks for it (gl/program.h's ProgramKey fields).
struct ProgramCase {
    std::string name;
    std::string vertex, fragment;
    std::vector<std::string> defines;
};

// gtest prints parameters in failure messages; a name beats a byte dump.
void PrintTo(const ProgramCase& c, std::ostream* os) { *os << c.name; }

// The defines renderer.cpp asks for (passes/shader_plan.cpp) for a pass that
// draws one object of each of `models` under `lights`.
std::vector<std::string> defines_for(ShaderMode mode, const std::vector<std::string>& models,
                                     const std::vector<Light>& lights, bool translucent_pass = false) {
    std::vector<Object> objects(models.size());
    std::vector<const Object*> pointers;
    for (std::size_t i = 0; i < models.size(); ++i) {
        objects[i].material = Material::of(models[i]);
        pointers.push_back(&objects[i]);
    }
    std::vector<std::string> defines = specialization_defines(mode, pointers, lights);
    if (translucent_pass) defines.push_back("TRANSLUCENT_PASS");
    return defines;
}

std::vector<std::string> general(bool translucent_pass = false) {
    return defines_for(ShaderMode::general, {}, {}, translucent_pass);
}

std::vector<std::string> specialized(const std::vector<std::string>& models, const std::vector<Light>& lights,
                                     bool translucent_pass = false) {
    return defines_for(ShaderMode::specialized, models, lights, translucent_pass);
}

// The same translucent pass for the blend without dual sources (passes/translucent_blend.h).
std::vector<std::string> two_pass(std::vector<std::string> defines) {
    defines.push_back(kTwoPassBlendDefine);
    return defines;
}

Light light_of(LightType type, std::vector<Lobe> lobes = {}) {
    Light light;
    light.type = type;
    light.lobes = std::move(lobes);
    return light;
}

Light shadowed(Light light) {
    light.shadow = true;
    return light;
}

// With the area lights' closed form for a highlight's lobe (AreaSampling::lobe_closed_form).
std::vector<std::string> lobe_closed_form(std::vector<std::string> defines) {
    defines.push_back(kLobeClosedFormDefine);
    return defines;
}

// Every opaque model of the table (all but the translucent pass's).
std::vector<std::string> every_opaque_model() {
    std::vector<std::string> names;
    for (const ModelSpec& model : model_table().models())
        if (model.family != Family::translucent) names.push_back(model.name);
    return names;
}

// The programs renderer.cpp builds: general sphere programs (ShaderMode::general:
// every model and light kind chosen at run time), specialized ones
// (passes/shader_plan.cpp: SPECIALIZED, LIGHT_COUNT n and the HAS_* flags of
// one scene), each opaque and translucent, and the quantize pass. The
// specialized sets are representative corners: no lights, one light, every
// flag, each metal variant alone (metal.glsl branches on them).
std::vector<ProgramCase> renderer_programs() {
    const std::string vert = "passes/sphere.vert", frag = "passes/sphere.frag";
    const Light directional = light_of(LightType::directional);
    const Light beckmann_lobes = light_of(LightType::directional, {{0.01, 0.4}});
    const Light point = light_of(LightType::point), spot = light_of(LightType::spot);
    const Light rect = light_of(LightType::rect), disk = light_of(LightType::disk), sky = light_of(LightType::sky);
    return {
        {"quantize", "passes/fullscreen.vert", "passes/quantize.frag", {}},
        {"general_opaque", vert, frag, general()},
        {"general_translucent", vert, frag, general(true)},
        {"general_translucent_two_pass", vert, frag, two_pass(general(true))},
        {"highlight_no_light", vert, frag, specialized({"highlight"}, {})},
        {"highlight_one_light", vert, frag, specialized({"highlight"}, {directional})},
        {"metal_only", vert, frag, specialized({"metal"}, {directional, directional})},
        {"metal_blinn_only", vert, frag, specialized({"metal_blinn"}, {directional})},
        {"metal_phong_only", vert, frag, specialized({"metal_phong"}, {directional})},
        {"every_flag", vert, frag, specialized(every_opaque_model(), {beckmann_lobes, point, spot, directional})},
        {"translucent_no_light", vert, frag, specialized({"translucent"}, {}, true)},
        {"translucent_spot_lobes", vert, frag, specialized({"translucent"}, {beckmann_lobes, point, spot}, true)},
        {"translucent_two_pass", vert, frag, two_pass(specialized({"translucent"}, {point}, true))},
        // The mesh pass (planes, cubes, cylinders, tori: passes/mesh_pass.cpp).
        {"mesh_general_opaque", "passes/mesh.vert", "passes/mesh.frag", general()},
        {"mesh_general_translucent", "passes/mesh.vert", "passes/mesh.frag", general(true)},
        {"mesh_general_translucent_two_pass", "passes/mesh.vert", "passes/mesh.frag", two_pass(general(true))},
        {"mesh_highlight_one_light", "passes/mesh.vert", "passes/mesh.frag", specialized({"highlight"}, {directional})},
        // Rect, disk and sky lights with shadows, and a hard shadow alone.
        {"area_lights_shadows", vert, frag,
         specialized(every_opaque_model(), {shadowed(rect), disk, shadowed(sky), shadowed(point)})},
        {"area_lights_lobe_closed_form", vert, frag,
         lobe_closed_form(specialized(every_opaque_model(), {shadowed(rect), sky}))},
        {"area_lights_translucent", vert, frag, specialized({"translucent"}, {shadowed(disk), sky}, true)},
        {"hard_shadow_alone", "passes/mesh.vert", "passes/mesh.frag",
         specialized({"highlight"}, {shadowed(directional)})},
        {"mesh_general_area_lights", "passes/mesh.vert", "passes/mesh.frag",
         defines_for(ShaderMode::general, {}, {shadowed(rect), sky}, false)},
    };
}

class ComposedProgram : public ::testing::TestWithParam<ProgramCase> {
protected:
    // Composes one stage and writes it as DIR/NAME.EXT (the extension tells
    // glslangValidator the stage).
    std::string write_stage(const std::string& glsl_path, const std::string& ext) {
        const ComposedShader shader = compose_shader(glsl_path, GetParam().defines);
        EXPECT_FALSE(shader.files.empty());
        if (!shader.files.empty()) {
            EXPECT_EQ(shader.files.front(), "glsl/" + glsl_path);  // files name the source as a log shows it
        }
        EXPECT_EQ(shader.text.rfind("#version 330 core\n", 0), 0u) << glsl_path;
        const std::string file = dir_.file(GetParam().name + "." + ext);
        test::write_text(file, shader.text);
        return file;
    }
    TempDir dir_;
};

TEST_P(ComposedProgram, VertexShaderValidates) {
    const std::string file = write_stage(GetParam().vertex, "vert");
    const ToolRun run = run_glslang({file});
    EXPECT_EQ(run.exit_code, 0) << file << " (" << GetParam().vertex << "):\n" << run.output;
}

TEST_P(ComposedProgram, FragmentShaderValidates) {
    const std::string file = write_stage(GetParam().fragment, "frag");
    const ToolRun run = run_glslang({file});
    EXPECT_EQ(run.exit_code, 0) << file << " (" << GetParam().fragment << "):\n" << run.output;
}

// -l links the two stages: the vertex outputs must match the fragment inputs.
TEST_P(ComposedProgram, StagesLinkTogether) {
    const std::string vert = write_stage(GetParam().vertex, "vert");
    const std::string frag = write_stage(GetParam().fragment, "frag");
    const ToolRun run = run_glslang({"-l", vert, frag});
    EXPECT_EQ(run.exit_code, 0) << run.output;
}

INSTANTIATE_TEST_SUITE_P(Renderer, ComposedProgram, ::testing::ValuesIn(renderer_programs()),
                         [](const ::testing::TestParamInfo<ProgramCase>& info) { return info.param.name; });

// The specialized programs the renderer really builds for the repository's
// scenes and the independent reference scenes (keys from passes/shader_plan.cpp,
// split into opaque and translucent passes as renderer.cpp splits them).
TEST(SceneProgram, EverySceneSpecializationValidatesAndLinks) {
    namespace fs = std::filesystem;
    std::vector<fs::path> scenes;
    for (const std::string& dir : {test::source_path("scenes"), test::reference_image_path("")})
        for (const auto& entry : fs::directory_iterator(dir))
            if (entry.path().extension() == ".json") scenes.push_back(entry.path());
    ASSERT_GE(scenes.size(), 13u);  // fig05..fig13, spec_example, three reference scenes

    std::set<std::vector<std::string>> keys;
    for (const auto& path : scenes) {
        const Scene scene = load_scene_file(path.string(), LoadContext::trusted());
        std::vector<const Object*> opaque, translucent;
        for (const Object& object : scene.objects)
            (is_translucent(object.material) ? translucent : opaque).push_back(&object);
        if (!opaque.empty()) keys.insert(specialization_defines(ShaderMode::specialized, opaque, scene.lights));
        if (!translucent.empty()) {
            auto defines = specialization_defines(ShaderMode::specialized, translucent, scene.lights);
            defines.push_back("TRANSLUCENT_PASS");
            keys.insert(defines);
        }
    }
    ASSERT_GE(keys.size(), 2u);
    TempDir dir;
    int index = 0;
    for (const auto& defines : keys) {
        std::string label;
        for (const auto& d : defines) label += " \"" + d + "\"";
        const std::string stem = dir.file("scene_program_" + std::to_string(index++));
        test::write_text(stem + ".vert", compose_shader("passes/sphere.vert", defines).text);
        test::write_text(stem + ".frag", compose_shader("passes/sphere.frag", defines).text);
        const ToolRun run = run_glslang({"-l", stem + ".vert", stem + ".frag"});
        EXPECT_EQ(run.exit_code, 0) << "defines" << label << ":\n" << run.output;
    }
    RecordProperty("distinct_programs", int(keys.size()));
}

// ---- GLSL ES 3.00 (WebGL2) ----------------------------------------------------

// The programs a WebGL2 build would compile, composed for GlslTarget::es: per
// model of the table its specialized sphere and mesh programs (the translucent
// family's translucent pass with the two-pass blend, as WebGL2 has no dual
// sources without an extension) and its BRDF grid program; the general
// programs; the quantize pass. glslangValidator takes the profile from
// "#version 300 es", so a desktop-only construct (an implicit int to float
// conversion, a samplerBuffer, a dual-source output) fails here, on the desktop.
std::vector<ProgramCase> es_programs() {
    const std::string vert = "passes/sphere.vert", frag = "passes/sphere.frag";
    const std::string mesh_vert = "passes/mesh.vert", mesh_frag = "passes/mesh.frag";
    const std::vector<Light> lights = {light_of(LightType::directional, {{0.01, 0.4}}), light_of(LightType::point),
                                       light_of(LightType::spot)};
    std::vector<ProgramCase> cases = {
        {"quantize", "passes/fullscreen.vert", "passes/quantize.frag", {}},
        {"general_opaque", vert, frag, general()},
        {"general_translucent_two_pass", vert, frag, two_pass(general(true))},
        {"mesh_general_opaque", mesh_vert, mesh_frag, general()},
        {"mesh_general_translucent_two_pass", mesh_vert, mesh_frag, two_pass(general(true))},
    };
    for (const ModelSpec& model : model_table().models()) {
        const bool translucent = model.family == Family::translucent;
        std::vector<std::string> defines = specialized({model.name}, lights, translucent);
        if (translucent) defines = two_pass(defines);
        cases.push_back({model.name, vert, frag, defines});
        cases.push_back({model.name + "_mesh", mesh_vert, mesh_frag, defines});
        if (!translucent)
            cases.push_back({model.name + "_brdf_grid", "passes/fullscreen.vert", "passes/brdf_grid.frag",
                             specialized({model.name}, {light_of(LightType::point)})});
    }
    return cases;
}

class EsProgram : public ::testing::TestWithParam<ProgramCase> {
protected:
    std::string write_stage(const std::string& glsl_path, const std::string& ext) {
        const ComposedShader shader = compose_shader(glsl_path, GetParam().defines, GlslTarget::es);
        EXPECT_EQ(shader.text.rfind("#version 300 es\n", 0), 0u) << glsl_path;
        const std::string file = dir_.file(GetParam().name + "." + ext);
        test::write_text(file, shader.text);
        return file;
    }
    TempDir dir_;
};

TEST_P(EsProgram, StagesValidateAndLinkAsGlslEs300) {
    const std::string vert = write_stage(GetParam().vertex, "vert");
    const std::string frag = write_stage(GetParam().fragment, "frag");
    const ToolRun run = run_glslang({"-l", vert, frag});
    EXPECT_EQ(run.exit_code, 0) << GetParam().vertex << " + " << GetParam().fragment << ":\n" << run.output;
}

INSTANTIATE_TEST_SUITE_P(WebGl2, EsProgram, ::testing::ValuesIn(es_programs()),
                         [](const ::testing::TestParamInfo<ProgramCase>& info) { return info.param.name; });

// The ES check can fail: a desktop-only construct (GLSL ES has no implicit int
// to float conversion) is rejected in the ES profile, accepted in the desktop one.
TEST(GlslangHarness, DesktopOnlyConstructFailsInTheEsProfile) {
    TempDir dir;
    const std::string body = "out vec4 color;\nvoid main() { float x = max(gl_FragCoord.x, 0); color = vec4(x); }\n";
    const std::string es = dir.file("implicit.frag"), desktop = dir.file("implicit_desktop.frag");
    test::write_text(es, glsl_header(GlslTarget::es) + body);
    test::write_text(desktop, glsl_header(GlslTarget::desktop) + body);
    EXPECT_NE(run_glslang({es}).exit_code, 0);
    EXPECT_EQ(run_glslang({desktop}).exit_code, 0);
}

// The desktop composition is what it was: the ES target changes only the header.
TEST(ComposeShader, EsTargetDiffersFromDesktopOnlyInTheHeader) {
    const std::vector<std::string> defines = general(true);
    const std::string desktop = compose_shader("passes/sphere.frag", defines).text;
    const std::string es = compose_shader("passes/sphere.frag", defines, GlslTarget::es).text;
    ASSERT_EQ(desktop.rfind(glsl_header(GlslTarget::desktop), 0), 0u);
    ASSERT_EQ(es.rfind(glsl_header(GlslTarget::es), 0), 0u);
    EXPECT_EQ(desktop.substr(glsl_header(GlslTarget::desktop).size()), es.substr(glsl_header(GlslTarget::es).size()));
}

// The harness can fail: a broken shader is rejected, with its error in the log.
TEST(GlslangHarness, BrokenShaderFails) {
    TempDir dir;
    const std::string file = dir.file("broken.frag");
    test::write_text(file,
                     "#version 330 core\n"
                     "out vec4 color;\n"
                     "void main() { color = vec4(undeclared_value, 1.0); }\n");
    const ToolRun run = run_glslang({file});
    EXPECT_NE(run.exit_code, 0) << run.output;
    EXPECT_NE(run.output.find("undeclared_value"), std::string::npos) << run.output;
}

// And a composed shader with one wrong line is rejected too (the #line
// directives that compose_shader inserts do not hide errors).
TEST(GlslangHarness, ComposedShaderWithAnErrorFails) {
    TempDir dir;
    ComposedShader shader = compose_shader("passes/quantize.frag", {});
    shader.text += "float broken = vec3(1.0);\n";  // type mismatch
    const std::string file = dir.file("broken_quantize.frag");
    test::write_text(file, shader.text);
    const ToolRun run = run_glslang({file});
    EXPECT_NE(run.exit_code, 0) << run.output;
}

TEST(ComposeShader, UnknownFileThrowsNamingIt) {
    try {
        compose_shader("passes/no_such.frag", {});
        FAIL() << "no exception";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("passes/no_such.frag"), std::string::npos) << error.what();
    }
}

// ---- annotate_shader_log -------------------------------------------------------

TEST(AnnotateShaderLog, MesaPrefixBecomesGlslPathLineColumn) {
    EXPECT_EQ(annotate_shader_log("0:12(5): error: x", {"glsl/a.glsl"}), "glsl/a.glsl:12:5: error: x");
}

TEST(AnnotateShaderLog, EachLineUsesItsOwnSourceNumber) {
    const std::vector<std::string> files = {"glsl/passes/sphere.frag", "glsl/terms/beckmann.glsl"};
    EXPECT_EQ(annotate_shader_log("0:3(1): error: a\n1:20(7): warning: b\n", files),
              "glsl/passes/sphere.frag:3:1: error: a\nglsl/terms/beckmann.glsl:20:7: warning: b\n");
}

TEST(AnnotateShaderLog, OtherDriversStyleAndUnknownNumbers) {
    // "N(LINE)" without a column (other drivers' style).
    EXPECT_EQ(annotate_shader_log("0(7) : error C0000: y", {"glsl/a.glsl"}), "glsl/a.glsl:7 : error C0000: y");
    // A source number beyond the file list is named as a number, not invented.
    EXPECT_EQ(annotate_shader_log("3:4(2): error: z", {"glsl/a.glsl"}), "source 3:4:2: error: z");
    // Text without a prefix is left alone.
    EXPECT_EQ(annotate_shader_log("link error: no main", {"glsl/a.glsl"}), "link error: no main");
}

// WebGL's compiler (ANGLE; glslang writes the same) puts the severity first:
// "ERROR: N:LINE: ...". A .brdf block's line is the file's own.
TEST(AnnotateShaderLog, WebGlPrefixBecomesFileLineAndSeverity) {
    const std::vector<std::string> files = {"glsl/passes/sphere.frag", "mine.brdf"};
    EXPECT_EQ(annotate_shader_log("ERROR: 0:12: 'x' : undeclared identifier\nWARNING: 1:1000008: 'y' : z", files),
              "glsl/passes/sphere.frag:12: error: 'x' : undeclared identifier\nmine.brdf:8: warning: 'y' : z");
}

}  // namespace
}  // namespace m3055
