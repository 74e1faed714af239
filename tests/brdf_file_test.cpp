// The .brdf parser (renderer/brdf_file/brdf_file.h): every line form BRDF
// Explorer's files use, and each malformed input as one line naming the file
// and its line.
#include "brdf_file/brdf_file.h"
#include "brdf_file/brdf_glsl.h"

#include <gtest/gtest.h>

#include <random>

namespace m3055 {
namespace {

const std::string kShader = "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec3(k); }\n";

std::string file_with(const std::string& params, const std::string& shader = kShader) {
    return "analytic\n# a comment\n::begin parameters\n" + params + "::end parameters\n::begin shader\n" + shader +
           "::end shader\n";
}

// The message of parsing `text`, "" if it parses.
std::string error_of(const std::string& text) {
    try {
        parse_brdf(text, "t.brdf");
    } catch (const BrdfError& e) {
        return e.what();
    }
    return std::string();
}

TEST(BrdfFile, ReadsEveryParameterForm) {
    const BrdfFile f = parse_brdf(file_with("float k 0 2 .5\ncolor baseColor .82 .67 .16\nbool  normalized 1\n"
                                            "bool zeroToOne false\n"),
                                  "t.brdf");
    ASSERT_EQ(f.params.size(), 4u);
    EXPECT_EQ(f.params[0].kind, BrdfParam::Kind::number);
    EXPECT_EQ(f.params[0].name, "k");
    EXPECT_EQ(f.params[0].min, 0.0);
    EXPECT_EQ(f.params[0].max, 2.0);
    EXPECT_EQ(f.params[0].fallback, std::vector<double>{0.5});
    EXPECT_EQ(f.params[0].line, 4);
    EXPECT_EQ(f.params[1].kind, BrdfParam::Kind::colour);
    EXPECT_EQ(f.params[1].fallback, (std::vector<double>{0.82, 0.67, 0.16}));
    EXPECT_EQ(f.params[2].kind, BrdfParam::Kind::flag);
    EXPECT_EQ(f.params[2].fallback, std::vector<double>{1.0});
    EXPECT_EQ(f.params[3].fallback, std::vector<double>{0.0});
    EXPECT_EQ(f.shader, kShader);
    EXPECT_EQ(f.shader_line, 10);  // the line after "::begin shader"
}

TEST(BrdfFile, CrlfNoTrailingNewlineAndCommentsInBlocksReadTheSame) {
    const std::string lf = file_with("float k 0 1 0.5\n");
    std::string crlf;
    for (char c : lf) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    std::string bare = lf;
    bare.pop_back();
    const std::string commented = "analytic\n::begin parameters\n# type name min max default\n\n"
                                  "float k 0 1 0.5   # the exponent\n::end parameters\n::begin shader\n" +
                                  kShader + "::end shader";
    for (const std::string& text : {lf, crlf, bare, commented}) {
        const BrdfFile f = parse_brdf(text, "t.brdf");
        ASSERT_EQ(f.params.size(), 1u);
        EXPECT_EQ(f.params[0].name, "k");
        EXPECT_EQ(f.params[0].fallback, std::vector<double>{0.5});
        EXPECT_EQ(f.shader, kShader);
    }
}

TEST(BrdfFile, EachProblemIsOneLineWithTheFilesLine) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"nothing\n", "t.brdf:1: the first line must be \"analytic\", got \"nothing\""},
        {"", "t.brdf: empty: the first line must be \"analytic\""},
        {file_with("float k 0 1\n"), "t.brdf:4: \"float\" needs 4 fields after it, got 3 in \"float k 0 1\""},
        {file_with("float k 0 one 0\n"), "t.brdf:4: k: MAX must be a finite number, got \"one\""},
        {file_with("float k 0 1 2\n"), "t.brdf:4: k: DEFAULT 2 is outside [0, 1]"},
        {file_with("float k 1 0 0.5\n"), "t.brdf:4: k: MIN 1 is above MAX 0"},
        {file_with("int k 0 1 0\n"), "t.brdf:4: a parameter line is \"float NAME MIN MAX DEFAULT\", \"color NAME R G "
                                     "B\" or \"bool NAME DEFAULT\", got \"int k 0 1 0\""},
        {file_with("color c 0.5 2 0\n"), "t.brdf:4: c: a colour component must be in [0, 1], got 2"},
        {file_with("bool b maybe\n"), "t.brdf:4: b: a bool's DEFAULT is 0, 1, true or false, got \"maybe\""},
        {file_with("float k 0 1 0\nfloat k 0 1 0\n"), "t.brdf:5: parameter \"k\" declared twice"},
        {file_with("float 2k 0 1 0\n"),
         "t.brdf:4: parameter name \"2k\" is not a GLSL identifier (letters, digits, _; at most 64)"},
        {file_with("float k 0 1 0\n", "float f() { return 1.0; }\n"),
         "t.brdf:6: the shader block defines no \"vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)\""},
        {file_with("float k 0 1 0\n", "// vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {}\n"),
         "t.brdf:6: the shader block defines no \"vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)\""},
        {"analytic\n::begin shader\n" + kShader, "t.brdf:2: the block is not closed by \"::end shader\""},
        {"analytic\n::begin parameters\n", "t.brdf:2: the block is not closed by \"::end parameters\""},
        {"analytic\n", "t.brdf: no \"::begin shader\" block"},
        {"analytic\nfloat k 0 1 0\n", "t.brdf:2: expected \"::begin parameters\" or \"::begin shader\", got \"float k 0 1 0\""},
        {file_with("") + "::begin shader\n::end shader\n", "t.brdf:8: a second \"::begin shader\" block"},
    };
    for (const auto& [text, message] : cases) EXPECT_EQ(error_of(text), message) << text;
}

TEST(BrdfFile, ParameterNamesMayNotBeGlslOrRendererNames) {
    for (const char* name : {"float", "uniform", "pow", "dot", "texture", "gl_Position", "a__b", "BRDF", "N", "L",
                             "mat", "Material", "PI", "u_light_count", "m3055_b0_k", "HAS_LAMBERT", "MAX_LIGHTS"}) {
        const std::string message = error_of(file_with(std::string("float ") + name + " 0 1 0\n"));
        EXPECT_EQ(message, "t.brdf:4: parameter name \"" + std::string(name) +
                               "\" is a GLSL keyword or built-in, or a name the renderer uses");
    }
    for (const char* name : {"roughness", "baseColor", "n", "kd", "axis", "sheenTint"})
        EXPECT_EQ(error_of(file_with(std::string("float ") + name + " 0 1 0\n")), "") << name;
}

TEST(BrdfFile, TopLevelNamesAreTheDeclarationsOutsideBraces) {
    const BrdfTopLevel names = brdf_top_level_names(
        "const float PI = 3.14159;\n#define SQR(x) ((x)*(x))\nfloat sqr(float x) { float y = x; return x * x; }\n"
        "struct Lobe { float w; };\nconst float INV = 1.0 / PI; // float commented(\n"
        "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec3(sqrt(2.0)); }\n");
    EXPECT_EQ(names.declared, (std::set<std::string>{"BRDF", "INV", "Lobe", "PI", "sqr"}));
    EXPECT_EQ(names.macros, std::set<std::string>{"SQR"});
}

// Random edits of a real-looking file: the parser either reads it or throws
// one BrdfError line; nothing else (scripts/fuzz does the same for longer).
TEST(BrdfFile, RandomEditsGiveAFileOrOneLine) {
    const std::string base = file_with("float k 0 1 0.5\ncolor c 1 0 0\nbool b 1\n");
    const std::string alphabet = "analytic:begin end parameters shader float color bool #\r\n 0.5 1e309 -";
    std::mt19937 random(13);
    for (int i = 0; i < 3000; ++i) {
        std::string text = base;
        for (int edits = 1 + int(random() % 4); edits > 0; --edits) {
            const std::size_t at = random() % (text.size() + 1);
            if (random() % 2) text.erase(at, random() % 8);
            else text.insert(at, 1, alphabet[random() % alphabet.size()]);
        }
        try {
            parse_brdf(text, "t.brdf");
        } catch (const BrdfError& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            EXPECT_EQ(message.rfind("t.brdf", 0), 0u) << message;
        }
    }
}

}  // namespace
}  // namespace m3055
