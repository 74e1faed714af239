// Composes a shader from glsl/ files: resolves `#include "path"` (each file
// once), inserts #defines after #version, and numbers every file in #line
// directives so a GL compile log can name the file and line.
#pragma once

#include <string>
#include <vector>

namespace m3055 {

struct ComposedShader {
    std::string text;                // ready for glShaderSource
    std::vector<std::string> files;  // source-string number -> glsl/ path
};

// Throws std::runtime_error naming the file when a path or include is unknown.
ComposedShader compose_shader(const std::string& path, const std::vector<std::string>& defines);

// Rewrites a GL info log's "N:LINE(COL)" / "N(LINE)" prefixes to "glsl/PATH:LINE".
std::string annotate_shader_log(const std::string& log, const std::vector<std::string>& files);

// The embedded text of one glsl/ file, or nullptr.
const char* find_glsl_source(const std::string& path);

}  // namespace m3055
