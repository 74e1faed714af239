// The Khronos reference compiler (glslangValidator, Debian's glslang-tools),
// run without a shell by the tests that validate composed shaders
// (glsl_validate_test: every program; brdf_glsl_es_test: .brdf files as GLSL ES).
// A missing glslangValidator is a failure, not a skip.
#pragma once

#include <string>
#include <vector>

namespace m3055::test {

struct ToolRun {
    int exit_code = -1;
    std::string output;  // stdout and stderr together
};

// Full path of `name` on $PATH, or "".
std::string find_in_path(const std::string& name);

// Runs glslangValidator with `args`; the calling test fails when it is missing.
ToolRun run_glslang(const std::vector<std::string>& args);

}  // namespace m3055::test
