// GL programs composed from glsl/ files, compiled once per specialization.
#pragma once

#include "gl/gl_api.h"
#include "gl/gl_object.h"
#include "gl/shader_error.h"

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace m3055 {

struct ProgramKey {
    std::string vertex, fragment;     // glsl/ paths
    std::vector<std::string> defines; // e.g. "TRANSLUCENT_PASS", "MAX_LIGHTS 4"
    // The model table's revision the program was built from (ProgramCache sets
    // it): the generated GLSL changes when a model is added at run time.
    std::uint64_t table_revision = 0;
    bool operator<(const ProgramKey& other) const;
};

// How every command (and the page) prints an error: "m3055: " and what() on
// one line (io/message_text's one_line), a ShaderError's log whole.
std::string error_text(const std::exception& error);

// Builds a program; throws ShaderError carrying the GL log with glsl/
// file names and lines when compiling or linking fails.
unsigned build_program(const GlApi& gl, const ProgramKey& key);

// The programs of one GL context, each built once. One cache per context,
// shared by everything that draws there (the renderers, the BRDF grid), so
// that no program is compiled twice.
class ProgramCache {
public:
    explicit ProgramCache(const GlApi& gl) : gl_(gl) {}

    unsigned get(ProgramKey key);
    // Whether get(key) would find the program built already (no compile).
    bool contains(ProgramKey key) const;
    std::size_t size() const { return programs_.size(); }

private:
    const GlApi& gl_;
    std::map<ProgramKey, GlProgram> programs_;
};

}  // namespace m3055
