// The glsl/ folder, embedded into the binary at build time
// (cmake/embed_files.cmake), so the program needs no shader files at run time.
#pragma once

#include <string>
#include <vector>

namespace m3055 {

struct GlslSource {
    const char* path;  // relative to glsl/, e.g. "terms/beckmann.glsl"
    const char* text;
};

const std::vector<GlslSource>& glsl_sources();

}  // namespace m3055
