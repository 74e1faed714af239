// Composes a shader from glsl/ files and the files generated from the model
// table (models/glsl_generator.h): resolves `#include "path"`, inserts
// #defines after #version, and numbers every file in #line directives so a GL
// compile log can name the file and line. Each included file is wrapped in an
// include guard and inlined where it is included, so a file first included
// inside an inactive #if block is still there where a later #include needs it.
#pragma once

#include <string>
#include <vector>

namespace m3055 {

struct ComposedShader {
    std::string text;                // ready for glShaderSource
    std::vector<std::string> files;  // source-string number -> "glsl/PATH" (or "generated/PATH")
    std::vector<std::string> user_files;  // those that are .brdf files' code (brdf_file/brdf_glsl.h)
};

// Files that are not in glsl/: (path, text), e.g. models/glsl_generator.h's.
using ExtraSources = std::vector<std::pair<std::string, std::string>>;

// The GLSL a shader is composed for. desktop: "#version 330 core", what every
// desktop program compiles. es: "#version 300 es" with highp defaults for
// float, int and sampler2D (GLSL ES 3.00 has no default float precision in
// fragment shaders, and float textures need highp samplers) and M3055_GLSL_ES
// defined: what WebGL2 compiles.
enum class GlslTarget { desktop, es };
// What this build's contexts compile: WebGL2's in the browser build (Emscripten).
#ifdef __EMSCRIPTEN__
inline constexpr GlslTarget kContextGlsl = GlslTarget::es;
#else
inline constexpr GlslTarget kContextGlsl = GlslTarget::desktop;
#endif

// The first lines of a composed shader for `target`, up to the defines.
std::string glsl_header(GlslTarget target);

// Throws std::runtime_error naming the file when a path or include is unknown
// or an include is circular. `extra` defaults to the model table's files.
ComposedShader compose_shader(const std::string& path, const std::vector<std::string>& defines,
                              GlslTarget target = kContextGlsl);
ComposedShader compose_shader(const std::string& path, const std::vector<std::string>& defines,
                              const ExtraSources& extra, GlslTarget target = kContextGlsl);

// Rewrites a GL info log's "N:LINE(COL)" / "N(LINE)" prefixes to "glsl/PATH:LINE".
std::string annotate_shader_log(const std::string& log, const std::vector<std::string>& files);

// The embedded text of one glsl/ file, or nullptr.
const char* find_glsl_source(const std::string& path);

}  // namespace m3055
