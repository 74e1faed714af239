// Shader compile and link failures: the exception carries the GL
// driver's log with the composed source's string numbers rewritten to glsl/
// file names and lines (gl/shader_source.h), and nothing crashes. The broken
// shaders are made from the real ones through the composer's own #define
// mechanism, so the product's glsl/ files stay untouched.
#include "gl/context.h"
#include "gl/program.h"
#include "gl/shader_source.h"
#include "passes/shader_plan.h"

#include <gtest/gtest.h>

#include <cctype>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace m3055 {
namespace {

const GlApi& gl() {
    static std::unique_ptr<HeadlessContext> context = HeadlessContext::create(Backend::automatic);
    return context->gl();
}

// 1-based line of the first line of glsl/`path` that contains `text`.
int line_of(const std::string& path, const std::string& text) {
    const char* source = find_glsl_source(path);
    if (!source) return -1;
    std::istringstream lines(source);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number)
        if (line.find(text) != std::string::npos) return number;
    return -1;
}

std::string build_error(const ProgramKey& key) {
    try {
        const unsigned program = build_program(gl(), key);
        gl().DeleteProgram(program);
    } catch (const std::exception& error) {
        return error.what();
    }
    return "";
}

// The general sphere program's defines (every model, as the renderer builds it:
// a model's GLSL is included only under its HAS_* define) plus `extra`.
std::vector<std::string> general_defines_and(const std::string& extra) {
    std::vector<std::string> defines = specialization_defines(ShaderMode::general, {}, {});
    defines.push_back(extra);
    return defines;
}

// Defining a function's name to a number turns its declaration into a syntax
// error in that function's own file.
TEST(ShaderErrors, CompileErrorNamesTheGlslFileAndLine) {
    const int line = line_of("terms/highlight_blend.glsl", "vec3 highlight_to_white(");
    ASSERT_GT(line, 0) << "glsl/terms/highlight_blend.glsl no longer declares highlight_to_white";
    const std::string error =
        build_error({"passes/sphere.vert", "passes/sphere.frag", general_defines_and("highlight_to_white 0")});
    ASSERT_NE(error, "") << "the broken shader compiled";
    EXPECT_EQ(error.rfind("cannot compile glsl/passes/sphere.frag:\n", 0), 0u) << error;
    EXPECT_NE(error.find("glsl/terms/highlight_blend.glsl:" + std::to_string(line) + ":"), std::string::npos)
        << error;
    EXPECT_NE(error.find("error"), std::string::npos) << error;
    // Every driver position is rewritten: no raw "N:LINE(COL)" prefix is left.
    std::istringstream lines(error);
    std::string entry;
    std::getline(lines, entry);  // the "cannot compile" header
    while (std::getline(lines, entry))
        if (!entry.empty() && std::isdigit(static_cast<unsigned char>(entry[0])))
            ADD_FAILURE() << "unannotated log line: " << entry;
}

// The composer's defines go into both stages; the vertex stage fails first.
TEST(ShaderErrors, CompileErrorInTheMainFileNamesIt) {
    const int line = line_of("passes/fullscreen.vert", "void main(");
    ASSERT_GT(line, 0);
    const std::string error = build_error({"passes/fullscreen.vert", "passes/quantize.frag", {"main 1"}});
    EXPECT_EQ(error.rfind("cannot compile glsl/passes/fullscreen.vert:\n", 0), 0u) << error;
    EXPECT_NE(error.find("glsl/passes/fullscreen.vert:" + std::to_string(line) + ":"), std::string::npos) << error;
}

// A fragment "shader" without main() (a library file that compiles on its
// own) cannot link.
TEST(ShaderErrors, LinkErrorNamesBothStagesAndCarriesTheLog) {
    const std::string error = build_error({"passes/fullscreen.vert", "common/math.glsl", {}});
    ASSERT_NE(error, "") << "a program without a fragment main() linked";
    EXPECT_EQ(error.rfind("cannot link glsl/passes/fullscreen.vert + glsl/common/math.glsl: ", 0), 0u) << error;
    EXPECT_NE(error.find("main"), std::string::npos) << error;  // Mesa: "fragment shader lacks `main'"
}

TEST(ShaderErrors, ContextStaysUsableAfterFailures) {
    EXPECT_NE(build_error({"passes/sphere.vert", "passes/sphere.frag", general_defines_and("highlight_to_white 0")}),
              "");
    EXPECT_EQ(build_error({"passes/fullscreen.vert", "passes/quantize.frag", {}}), "");
}

TEST(ShaderErrors, UnknownFileIsAnErrorNotACrash) {
    EXPECT_EQ(build_error({"passes/fullscreen.vert", "passes/no_such.frag", {}}),
              "compose_shader: unknown glsl file \"passes/no_such.frag\"");
}

}  // namespace
}  // namespace m3055
