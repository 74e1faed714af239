// .brdf files as people write them, compiled as GLSL ES 3.00 (WebGL2):
// the translator's conversions one by one (brdf_file/brdf_glsl_es.h), then
// whole files loaded as the renderer loads them, composed for GlslTarget::es
// and validated by glslangValidator's ES profile, and a broken file's error
// still naming the .brdf's own line; and a translated block, rendered by the
// desktop renderer, draws the same bytes as the file's own.
//
// BRDF Explorer's 40 files (github.com/wdas/brdf, src/brdfs/) are third-party
// and not in this repository: set M3055_BRDF_EXPLORER_BRDFS to a folder
// holding them (e.g. a checkout's src/brdfs) and the test validates each;
// without it that one test is skipped, saying so.
#include "brdf_file/brdf_file.h"
#include "brdf_file/brdf_glsl.h"
#include "brdf_file/brdf_glsl_es.h"
#include "brdf_file/brdf_model.h"
#include "gl/shader_source.h"
#include "glslang_tool.h"
#include "models/model_table.h"
#include "passes/shader_plan.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace m3055 {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

std::string es(const std::string& glsl, const std::vector<std::pair<std::string, std::string>>& globals = {}) {
    const GlslEsTranslation t = translate_glsl_es(glsl, globals);
    EXPECT_EQ(t.stopped, "") << glsl;
    return t.text;
}

// ---- each conversion --------------------------------------------------------------

TEST(GlslEsConversions, IntLiteralArgumentOfAFloatBuiltin) {
    EXPECT_EQ(es("float f(float x) { return max(x, 0); }"), "float f(float x) { return max(x, 0.0); }");
    EXPECT_EQ(es("float f(float x) { return pow(x, 2); }"), "float f(float x) { return pow(x, 2.0); }");
    // Float-only built-ins take floats even when every argument is an int.
    EXPECT_EQ(es("float f() { return sqrt(2); }"), "float f() { return sqrt(2.0); }");
    EXPECT_EQ(es("vec3 f(vec3 v) { return clamp(v, 0, 1); }"), "vec3 f(vec3 v) { return clamp(v, 0.0, 1.0); }");
    EXPECT_EQ(es("float f(float a) { return smoothstep(0, 1, a); }"), "float f(float a) { return smoothstep(0.0, 1.0, a); }");
}

TEST(GlslEsConversions, IntOnlyCallsAndIntegerOperatorsStayInts) {
    // max, min, clamp, abs have int versions: all-int calls are not converted.
    EXPECT_EQ(es("int f(int i) { return max(i, 0) % 3; }"), "int f(int i) { return max(i, 0) % 3; }");
    // mix's bool selector is not a float argument.
    EXPECT_EQ(es("float f(bool b) { return mix(1, 2.5, b); }"), "float f(bool b) { return mix(1.0, 2.5, b); }");
}

TEST(GlslEsConversions, InitializersAssignmentsAndCompoundAssignments) {
    EXPECT_EQ(es("float a = 1;"), "float a = 1.0;");
    EXPECT_EQ(es("const float a = 1, b = 2.5, c = 3;"), "const float a = 1.0, b = 2.5, c = 3.0;");
    EXPECT_EQ(es("void f() { float a; a = 1; a += 2; a /= 3; }"), "void f() { float a; a = 1.0; a += 2.0; a /= 3.0; }");
    EXPECT_EQ(es("void f() { vec3 v; v *= 2; }"), "void f() { vec3 v; v *= 2.0; }");
    EXPECT_EQ(es("uint u = 1;"), "uint u = 1u;");
}

TEST(GlslEsConversions, ArithmeticAndComparisonOperands) {
    EXPECT_EQ(es("float f(float x) { return x * 2 + 1 - 3 / x; }"), "float f(float x) { return x * 2.0 + 1.0 - 3.0 / x; }");
    EXPECT_EQ(es("vec3 f(vec3 v) { return 2 * v / 4; }"), "vec3 f(vec3 v) { return 2.0 * v / 4.0; }");
    EXPECT_EQ(es("bool f(float x) { return x > 0 && x <= 1 || x == 2; }"),
              "bool f(float x) { return x > 0.0 && x <= 1.0 || x == 2.0; }");
    EXPECT_EQ(es("float f(vec3 v) { return v.x * 2 + v[1] * 3; }"), "float f(vec3 v) { return v.x * 2.0 + v[1] * 3.0; }");
}

TEST(GlslEsConversions, IntDivisionStaysAnIntDivisionAsOnTheDesktop) {
    // 1 / 2 is 0 on the desktop too: the int result is converted, not the operands.
    EXPECT_EQ(es("float f(float x) { return 1 / 2 * x; }"), "float f(float x) { return float(1 / 2) * x; }");
    EXPECT_EQ(es("float f(float x) { return x * (1 / 2 + 1); }"), "float f(float x) { return x * (float(1 / 2 + 1)); }");
}

TEST(GlslEsConversions, IntVariablesAndVectorsAreWrapped) {
    EXPECT_EQ(es("float f(int i) { return i; }"), "float f(int i) { return float(i); }");
    EXPECT_EQ(es("float f(int i, float x) { return x * i; }"), "float f(int i, float x) { return x * float(i); }");
    EXPECT_EQ(es("vec3 f(ivec3 i) { return i; }"), "vec3 f(ivec3 i) { return vec3(i); }");
    EXPECT_EQ(es("float f(int i) { return pow(2.0, i + 1); }"), "float f(int i) { return pow(2.0, float(i + 1)); }");
    EXPECT_EQ(es("uint f(int i) { return i; }"), "uint f(int i) { return uint(i); }");
}

TEST(GlslEsConversions, FloatLoopsArrayElementsAndMatrices) {
    EXPECT_EQ(es("float f() { float s = 0; for (float t = 0; t < 1; t += 0.25) s += t; return s; }"),
              "float f() { float s = 0.0; for (float t = 0.0; t < 1.0; t += 0.25) s += t; return s; }");
    EXPECT_EQ(es("void f() { float a[3]; a[0] = 1; vec3 v; v.x = 2; v.yz = vec2(3); }"),
              "void f() { float a[3]; a[0] = 1.0; vec3 v; v.x = 2.0; v.yz = vec2(3); }");
    EXPECT_EQ(es("vec3 f(mat3 m, vec3 v) { return m * v * 2 + m[0] / 2; }"),
              "vec3 f(mat3 m, vec3 v) { return m * v * 2.0 + m[0] / 2.0; }");
}

TEST(GlslEsConversions, LiteralForms) {
    EXPECT_EQ(es("float a = -1;"), "float a = -1.0;");
    EXPECT_EQ(es("float a = -(-(2));"), "float a = -(-(2.0));");
    EXPECT_EQ(es("float f(int i) { return -i; }"), "float f(int i) { return float(-i); }");
    EXPECT_EQ(es("float a = (2);"), "float a = (2.0);");
    EXPECT_EQ(es("float a = 0x10;"), "float a = float(0x10);");  // not 0x10.0
    EXPECT_EQ(es("float a = 010;"), "float a = float(010);");     // octal 8, not 10.0
    EXPECT_EQ(es("float a = 2u;"), "float a = float(2u);");
    EXPECT_EQ(es("float a = 1e2 + .5 + 2.f;"), "float a = 1e2 + .5 + 2.f;");
}

TEST(GlslEsConversions, ConditionalBranchesTakeTheOtherBranchsType) {
    EXPECT_EQ(es("float f(bool b, float x) { return b ? 1 : x; }"), "float f(bool b, float x) { return b ? 1.0 : x; }");
    // Both branches ints: the desktop converts the result, and so does the translation.
    EXPECT_EQ(es("float f(bool b) { return b ? 1 : 0; }"), "float f(bool b) { return float(b ? 1 : 0); }");
    EXPECT_EQ(es("int f(bool b) { return b ? 1 : 0; }"), "int f(bool b) { return b ? 1 : 0; }");
}

TEST(GlslEsConversions, ReturnOfAnIntFromAFloatFunction) {
    EXPECT_EQ(es("float one() { return 1; }\nvec3 v() { return vec3(0); }"),
              "float one() { return 1.0; }\nvec3 v() { return vec3(0); }");
}

TEST(GlslEsConversions, UserFunctionArgumentsFollowOverloadResolution) {
    EXPECT_EQ(es("float sqr(float x) { return x * x; }\nfloat a = sqr(2);"),
              "float sqr(float x) { return x * x; }\nfloat a = sqr(2.0);");
    // An exact int overload is chosen: nothing converts.
    EXPECT_EQ(es("float g(int i);\nfloat g(float x);\nfloat a = g(2);"), "float g(int i);\nfloat g(float x);\nfloat a = g(2);");
    // An in argument converts; an out argument takes no int -> float conversion (it
    // would be float -> int on the way back, which GLSL has not): no overload matches.
    EXPECT_EQ(es("void h(float a, out float b) { b = a; }\nvoid f() { float r; h(1, r); }"),
              "void h(float a, out float b) { b = a; }\nvoid f() { float r; h(1.0, r); }");
    EXPECT_EQ(es("void h(float a, out float b) { b = a; }\nvoid f() { int i; h(1, i); }"),
              "void h(float a, out float b) { b = a; }\nvoid f() { int i; h(1, i); }");
}

TEST(GlslEsConversions, StructAndArrayConstructors) {
    EXPECT_EQ(es("struct S { float a; int n; };\nS s = S(1, 2);"), "struct S { float a; int n; };\nS s = S(1.0, 2);");
    EXPECT_EQ(es("float w[2] = float[2](1, 2.5);"), "float w[2] = float[2](1.0, 2.5);");
    EXPECT_EQ(es("struct S { float a; };\nfloat f(S s) { return s.a * 2; }"),
              "struct S { float a; };\nfloat f(S s) { return s.a * 2.0; }");
}

TEST(GlslEsConversions, VectorConstructorsIndicesAndLoopsAreLeftAlone) {
    // GLSL ES constructors convert their arguments themselves; indices are ints.
    const std::string code =
        "float f(vec3 v, float x) {\n"
        "    vec3 a = vec3(0) + vec3(1, x, 2);\n"
        "    for (int i = 0; i < 3; i++) a[i] += v[2 - i];\n"
        "    mat2 m = mat2(1);\n"
        "    return a[0] + m[1][1];\n"
        "}\n";
    EXPECT_EQ(es(code), code);
}

TEST(GlslEsConversions, TheFilesParametersAreTyped) {
    EXPECT_EQ(es("float f() { return roughness * 2 + (flag ? 1 : 0); }", {{"float", "roughness"}, {"bool", "flag"}}),
              "float f() { return roughness * 2.0 + (float(flag ? 1 : 0)); }");
    EXPECT_EQ(es("vec3 f() { return base / 2; }", {{"vec3", "base"}}), "vec3 f() { return base / 2.0; }");
}

TEST(GlslEsConversions, UnknownTypesAreLeftForTheCompilerToName) {
    // A macro or an undeclared name: its type is not known, so nothing around it changes.
    const std::string code = "#define K 2.0\nfloat f() { return K * 2 + undeclared * 3; }\n";
    EXPECT_EQ(es(code), code);
}

TEST(GlslEsConversions, CommentsAndPreprocessorLinesAreUntouched) {
    EXPECT_EQ(es("// float a = 1;\n/* max(x, 0) */ float b = 1; // 2\n#if 1\n#endif\n"),
              "// float a = 1;\n/* max(x, 0) */ float b = 1.0; // 2\n#if 1\n#endif\n");
}

TEST(GlslEsConversions, ScopesShadow) {
    // A local int named like a global float is an int inside its block.
    EXPECT_EQ(es("float k = 1;\nfloat f() { int k = 2; float a = k; { float k = 3; a += k; } return a; }"),
              "float k = 1.0;\nfloat f() { int k = 2; float a = float(k); { float k = 3.0; a += k; } return a; }");
}

TEST(GlslEsConversions, RedefinedBuiltinsAreReported) {
    const GlslEsTranslation t = translate_glsl_es("vec3 reflect(vec3 I, vec3 N) { return 2 * dot(I, N) * N - I; }\n"
                                                  "float sqr(float x) { return x * x; }\n", {});
    EXPECT_EQ(t.redefined_builtins, std::vector<std::string>{"reflect"});
    EXPECT_EQ(t.text, "vec3 reflect(vec3 I, vec3 N) { return 2.0 * dot(I, N) * N - I; }\n"
                      "float sqr(float x) { return x * x; }\n");
    EXPECT_EQ(t.conversions, 1);
}

TEST(GlslEsConversions, ASyntaxErrorStopsThereKeepingEarlierConversions) {
    const GlslEsTranslation t = translate_glsl_es("float a = 1;\n\nfloat b = (2;\nfloat c = 3;\n", {});
    EXPECT_EQ(t.stopped.rfind("line 3: ", 0), 0u) << t.stopped;
    EXPECT_EQ(t.text, "float a = 1.0;\n\nfloat b = (2;\nfloat c = 3;\n");
}

TEST(GlslEsConversions, DeepNestingStopsTheTranslationNotTheProcess) {
    for (const std::string& open : {std::string("("), std::string("-"), std::string("{")}) {
        std::string code = open == "{" ? "float a = 1;\nvoid f() " : "float a = 1;\nvoid f() { float x = ";
        for (int i = 0; i < 100000; ++i) code += open;
        const GlslEsTranslation t = translate_glsl_es(code, {});
        EXPECT_EQ(t.stopped, "line 2: nested more than 200 deep") << open;
        EXPECT_EQ(t.text, "float a = 1.0;\n" + code.substr(code.find('\n') + 1)) << open;
    }
}

// ---- whole files, composed and validated -------------------------------------------

// The sphere program of one scene with `spec`'s material and a point light, as GLSL ES.
struct EsProgram {
    ComposedShader vert, frag;
};

EsProgram es_program(const ModelSpec& spec) {
    Object object;
    object.material = Material(spec);
    Light light;
    light.type = LightType::point;
    const std::vector<std::string> defines = specialization_defines(ShaderMode::specialized, {&object}, {light});
    return {compose_shader("passes/sphere.vert", defines, GlslTarget::es),
            compose_shader("passes/sphere.frag", defines, GlslTarget::es)};
}

// A name with "__" (GLSL ES 3.00 §3.8 reserves them): glslang lets it pass,
// WebGL's compiler (ANGLE, on every backend) refuses it. "" or the first one.
std::string reserved_name(const std::string& text) {
    static const std::regex name(R"([A-Za-z_][A-Za-z0-9_]*)");
    for (std::sregex_iterator it(text.begin(), text.end(), name), end; it != end; ++it) {
        const std::string found = it->str();
        if (found.find("__") != std::string::npos && found != "__LINE__" && found != "__FILE__" && found != "__VERSION__")
            return found;
    }
    return "";
}

// glslangValidator -l on the program, and no reserved name in it; "" when it
// validates, else its log.
std::string validate(const EsProgram& program) {
    for (const ComposedShader* stage : {&program.vert, &program.frag})
        if (const std::string found = reserved_name(stage->text); !found.empty())
            return "the name " + found + " contains \"__\", which WebGL refuses";
    TempDir dir;
    test::write_text(dir.file("p.vert"), program.vert.text);
    test::write_text(dir.file("p.frag"), program.frag.text);
    const test::ToolRun run = test::run_glslang({"-l", dir.file("p.vert"), dir.file("p.frag")});
    return run.exit_code == 0 ? std::string() : run.output.empty() ? std::string("(no output)") : run.output;
}

std::vector<std::string> brdf_files_in(const std::string& folder) {
    std::vector<std::string> out;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().extension() == ".brdf") out.push_back(entry.path().string());
    std::sort(out.begin(), out.end());
    return out;
}

bool broken(const std::string& path) { return fs::path(path).filename().string().rfind("broken_", 0) == 0; }

// The ES block is the desktop block with conversions inserted: same lines, and the
// desktop sources are still the file's own text.
void expect_same_lines(const ModelSpec& spec, const std::string& path) {
    ASSERT_EQ(spec.glsl_sources.size(), 2u) << path;
    ASSERT_EQ(spec.glsl_sources_es.size(), 2u) << path;
    const std::string& desktop = spec.glsl_sources[1].second;
    const std::string& es_block = spec.glsl_sources_es[1].second;
    EXPECT_EQ(std::count(desktop.begin(), desktop.end(), '\n'), std::count(es_block.begin(), es_block.end(), '\n'))
        << path;
    const BrdfModel* model = find_brdf_model(spec);
    ASSERT_NE(model, nullptr);
    EXPECT_NE(desktop.find(model->file.shader), std::string::npos) << path;
}

TEST(BrdfFilesAsGlslEs, OurTestFilesValidate) {
    int validated = 0;
    for (const std::string& path : brdf_files_in(test::source_path("tests/data/brdf"))) {
        if (broken(path)) continue;
        const ModelSpec& spec = *load_brdf_model(path).spec;
        expect_same_lines(spec, path);
        EXPECT_EQ(validate(es_program(spec)), "") << path;
        ++validated;
    }
    EXPECT_GE(validated, 4);
}

// The untranslated block fails as GLSL ES: the file needs the translation (the test can fail).
TEST(BrdfFilesAsGlslEs, DesktopDialectFileFailsUntranslated) {
    const ModelSpec& spec = *load_brdf_model(test::source_path("tests/data/brdf/desktop_dialect.brdf")).spec;
    EsProgram program = es_program(spec);
    const std::string translated_block = spec.glsl_sources_es[1].second;
    const std::string desktop_block = spec.glsl_sources[1].second;
    ASSERT_NE(translated_block, desktop_block);
    // The composed text holds the translated block's lines; put the desktop ones back.
    std::string& text = program.frag.text;
    std::size_t at = 0;
    int replaced = 0;
    std::istringstream es_lines(translated_block), desktop_lines(desktop_block);
    for (std::string a, b; std::getline(es_lines, a) && std::getline(desktop_lines, b);) {
        if (a == b || a.empty()) continue;
        at = text.find(a, at);
        ASSERT_NE(at, std::string::npos) << a;
        text.replace(at, a.size(), b);
        ++replaced;
    }
    EXPECT_GE(replaced, 10);
    EXPECT_NE(validate(program), "");
}

TEST(BrdfFilesAsGlslEs, BrdfExplorerFilesValidate) {
    const char* folder = std::getenv("M3055_BRDF_EXPLORER_BRDFS");
    if (!folder || !fs::is_directory(folder))
        GTEST_SKIP() << "M3055_BRDF_EXPLORER_BRDFS is not a folder: set it to BRDF Explorer's src/brdfs "
                        "(github.com/wdas/brdf) to validate its 40 files as GLSL ES";
    const std::vector<std::string> files = brdf_files_in(folder);
    int validated = 0;
    std::string failed;
    for (const std::string& path : files) {
        const ModelSpec& spec = *load_brdf_model(path).spec;
        expect_same_lines(spec, path);
        const std::string log = validate(es_program(spec));
        EXPECT_EQ(log, "") << path;
        if (log.empty()) ++validated;
        else failed += " " + fs::path(path).filename().string();
    }
    RecordProperty("files", int(files.size()));
    RecordProperty("validated", validated);
    std::cout << validated << " of " << files.size() << " BRDF Explorer files validate as GLSL ES 3.00"
              << (failed.empty() ? "" : "; not:" + failed) << "\n";
}

// ---- the translation computes what the file computes ---------------------------------

// `text` with its shader block replaced by the block's GLSL ES translation: the
// explicit conversions are desktop GLSL too, so the desktop renderer draws it.
std::string translated_file(const std::string& text, const std::string& name) {
    const BrdfFile file = parse_brdf(text, name);
    std::vector<std::pair<std::string, std::string>> globals;
    for (const BrdfParam& p : file.params)
        globals.push_back({p.kind == BrdfParam::Kind::number ? "float" : p.kind == BrdfParam::Kind::colour ? "vec3" : "bool",
                           p.name});
    const std::size_t at = text.find(file.shader);
    EXPECT_NE(at, std::string::npos) << name;
    return text.substr(0, at) + translate_glsl_es(file.shader, globals).text + text.substr(at + file.shader.size());
}

// `m3055 render` of a sphere of each of two .brdf texts, two lights: "" when
// the PNGs and the linear PFMs are byte-identical, else why not.
std::string render_same(const std::string& text, const std::string& other) {
    TempDir dir;
    test::write_text(dir.file("a.brdf"), text);
    test::write_text(dir.file("b.brdf"), other);
    for (const char* v : {"a", "b"}) {
        test::write_text(dir.file(std::string(v) + ".json"),
                         R"({"display": {"width": 96, "height": 96, "bits": 8}, "background": [0, 0, 0],
 "camera": {"projection": "orthographic", "position": [0, 0, 10], "target": [0, 0, 0], "up": [0, 1, 0], "height": 2.4},
 "lights": [{"type": "directional", "direction": [1, 1, 1], "intensity": 1.0, "color": [1, 1, 1]},
            {"type": "point", "position": [-3, 1, 4], "intensity": 0.5, "color": [1, 1, 1]}],
 "objects": [{"shape": "sphere", "center": [0, 0, 0], "radius": 1,
              "material": {"model": "brdf", "file": ")" + std::string(v) + R"(.brdf"}}]})");
        const test::RunResult r = test::run_m3055({"render", "--scene", dir.file(std::string(v) + ".json"), "--out",
                                                   dir.file(std::string(v) + ".png"), "--raw", dir.file(std::string(v) + ".pfm")});
        if (r.exit_code != 0) return std::string("render ") + v + ": " + r.err;
    }
    if (test::read_text(dir.file("a.png")) != test::read_text(dir.file("b.png"))) return "the PNGs differ";
    if (test::read_text(dir.file("a.pfm")) != test::read_text(dir.file("b.pfm"))) return "the PFMs differ";
    return "";
}

// A file and its translation draw the same bytes.
std::string renders_identically(const std::string& path) {
    const std::string text = test::read_text(path);
    const std::string translated = translated_file(text, path);
    return translated == text ? "" : render_same(text, translated);
}

// The comparison can fail: converting the literals of an int division (what a
// textual rewrite of every int literal does) changes desktop_dialect.brdf's picture.
TEST(BrdfFilesAsGlslEs, RewritingAnIntDivisionsLiteralsChangesThePicture) {
    const std::string text = test::read_text(test::source_path("tests/data/brdf/desktop_dialect.brdf"));
    const std::string translated = translated_file(text, "desktop_dialect.brdf");
    const std::string naive = std::regex_replace(translated, std::regex(R"(float\(1 / 2 \+ 1\))"), "1.0 / 2.0 + 1.0");
    ASSERT_NE(naive, translated);
    EXPECT_NE(render_same(translated, naive), "");
}

TEST(BrdfFilesAsGlslEs, TranslatedOwnFilesRenderIdenticallyOnTheDesktop) {
    int rendered = 0;
    for (const std::string& path : brdf_files_in(test::source_path("tests/data/brdf"))) {
        EXPECT_EQ(renders_identically(path), "") << path;
        ++rendered;
    }
    EXPECT_GE(rendered, 5);
}

TEST(BrdfFilesAsGlslEs, TranslatedBrdfExplorerFilesRenderIdenticallyOnTheDesktop) {
    const char* folder = std::getenv("M3055_BRDF_EXPLORER_BRDFS");
    if (!folder || !fs::is_directory(folder))
        GTEST_SKIP() << "M3055_BRDF_EXPLORER_BRDFS is not a folder (see BrdfExplorerFilesValidate)";
    for (const std::string& path : brdf_files_in(folder)) EXPECT_EQ(renders_identically(path), "") << path;
}

// ---- random expressions ---------------------------------------------------------------

// Random desktop GLSL mixing ints into float expressions everywhere the desktop
// allows (operands, built-ins' arguments, a user function's, ?: branches,
// comparisons, initializers, compound assignments), with int sub-expressions
// that must stay ints (%, int division, int max/abs, indices).
class RandomGlsl {
public:
    explicit RandomGlsl(unsigned seed) : random_(seed) {}

    std::string brdf(int statements) {
        std::string code =
            "analytic\n::begin parameters\nfloat a 0 1 0.3\nbool b 1\n::end parameters\n::begin shader\n"
            "float sqr(float t) { return t * t; }\n"
            "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)\n{\n"
            "    float x = dot(N, L);\n    int i = 3;\n    vec3 v = N;\n    float w[3] = float[3](0.5, 1, 2);\n"
            "    float acc = 0;\n";
        for (int k = 0; k < statements; ++k) {
            const int kind = pick(5);
            if (kind == 0) code += "    if (" + f(3) + " > " + i(2) + ") acc += 1;\n";
            else if (kind == 1) code += "    acc += 0.01 * clamp(dot(" + vec(2) + ", vec3(0.3, 1, -2)), -4, 4);\n";
            else code += "    acc += 0.01 * clamp(" + f(4) + ", -4, 4);\n";
        }
        return code + "    return vec3(0.5 + 0.1 * acc);\n}\n::end shader\n";
    }

private:
    std::mt19937 random_;
    int pick(int n) { return int(random_() % unsigned(n)); }

    std::string int_literal() { return std::to_string(pick(9) + 1); }

    std::string f(int depth) {
        if (depth == 0) {
            const std::string leaves[] = {"x", "a", "1.5", int_literal(), "i", "v.y", "w[i - 2]", "float(i)"};
            return leaves[pick(8)];
        }
        const int d = depth - 1;
        switch (pick(12)) {
            case 0: return "(" + f(d) + " + " + f(d) + ")";
            case 1: return "(" + f(d) + " - " + f(d) + ")";
            case 2: return "(" + f(d) + " * " + f(d) + ")";
            case 3: return "(" + f(d) + " / (" + f(d) + " + 9.5))";
            case 4: return "max(" + f(d) + ", " + f(d) + ")";
            case 5: return "pow(abs(" + f(d) + "), " + f(d) + " * 0.25)";
            case 6: return "clamp(" + f(d) + ", " + int_literal() + ", " + f(d) + " + 10)";
            case 7: return "(b ? " + f(d) + " : " + f(d) + ")";
            case 8: return "sqr(" + f(d) + ")";
            case 9: return "mix(" + f(d) + ", " + f(d) + ", " + f(d) + ")";
            case 10: return "-(" + f(d) + ")";
            default: return "(" + i(d) + ")";
        }
    }

    // vec3 expressions taking ints, int scalars and ivec3s.
    std::string vec(int depth) {
        if (depth == 0) {
            const std::string leaves[] = {"v", "N", "vec3(" + f(1) + ")", "ivec3(i, 2, " + i(1) + ")"};
            return leaves[pick(4)];
        }
        const int d = depth - 1;
        switch (pick(7)) {
            case 0: return "(" + vec(d) + " + " + vec(d) + ")";
            case 1: return "(" + vec(d) + " * " + f(d) + ")";
            case 2: return "(" + i(d) + " * " + vec(d) + ")";
            case 3: return "max(" + vec(d) + ", " + f(d) + ")";
            case 4: return "clamp(" + vec(d) + ", " + int_literal() + ", " + f(d) + " + 10)";
            case 5: return "mix(" + vec(d) + ", " + vec(d) + ", " + f(d) + ")";
            default: return "(" + vec(d) + " / (" + f(d) + " + 9.5))";
        }
    }

    std::string i(int depth) {
        if (depth == 0) return pick(2) ? "i" : int_literal();
        const int d = depth - 1;
        switch (pick(6)) {
            case 0: return "(" + i(d) + " + " + i(d) + ")";
            case 1: return "(" + i(d) + " / " + int_literal() + ")";
            case 2: return "(" + i(d) + " % 3)";
            case 3: return "max(" + i(d) + ", " + i(d) + ")";
            case 4: return "abs(" + i(d) + ")";
            default: return "(b ? " + i(d) + " : " + i(d) + ")";
        }
    }
};

TEST(BrdfFilesAsGlslEs, RandomExpressionsValidateAndRenderIdentically) {
    TempDir dir;
    int conversions = 0;
    for (unsigned seed = 1; seed <= 4; ++seed) {
        const std::string text = RandomGlsl(seed).brdf(30);
        const std::string path = dir.file("random_" + std::to_string(seed) + ".brdf");
        test::write_text(path, text);
        const ModelSpec& spec = *load_brdf_model(path).spec;
        expect_same_lines(spec, path);
        EXPECT_EQ(validate(es_program(spec)), "") << text;
        EXPECT_EQ(render_same(text, translated_file(text, path)), "") << text;
        const BrdfFile file = parse_brdf(text, path);
        conversions += translate_glsl_es(file.shader, {{"float", "a"}, {"bool", "b"}}).conversions;
    }
    EXPECT_GE(conversions, 100);
    RecordProperty("conversions", conversions);
}

// ---- errors still name the .brdf's line ---------------------------------------------

TEST(BrdfFilesAsGlslEs, ErrorNamesTheBrdfLine) {
    TempDir dir;
    const std::string path = dir.file("typo.brdf");
    // Line 7 converts (max(x, 0)); line 8 has the error (a vec3 into a float).
    test::write_text(path,
                     "analytic\n"
                     "::begin parameters\n"
                     "float gain 0 1 0.5\n"
                     "::end parameters\n"
                     "::begin shader\n"
                     "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {\n"
                     "    float d = max(dot(N, L), 0) * gain;\n"
                     "    float wrong = N * 2;\n"
                     "    return vec3(d);\n"
                     "}\n"
                     "::end shader\n");
    const ModelSpec& spec = *load_brdf_model(path).spec;
    const EsProgram program = es_program(spec);
    TempDir out;
    test::write_text(out.file("p.frag"), program.frag.text);
    const test::ToolRun run = test::run_glslang({out.file("p.frag")});
    ASSERT_NE(run.exit_code, 0) << run.output;
    // glslang writes "ERROR: SOURCE:LINE: ..."; as Mesa's "SOURCE:LINE(COL):" the
    // renderer's annotate_shader_log names the file and its line.
    const std::string as_mesa = std::regex_replace(run.output, std::regex(R"(ERROR: (\d+):(\d+):)"), "$1:$2(1): error:");
    const std::string annotated = annotate_shader_log(as_mesa, program.frag.files);
    EXPECT_NE(annotated.find("typo.brdf:8:1: error:"), std::string::npos) << annotated;
    EXPECT_EQ(annotated.find("typo.brdf:7:"), std::string::npos) << annotated;
}

}  // namespace
}  // namespace m3055
