// GL programs composed from glsl/ files, compiled once per specialization.
#pragma once

#include "gl/gl_api.h"

#include <map>
#include <string>
#include <vector>

namespace m3055 {

struct ProgramKey {
    std::string vertex, fragment;     // glsl/ paths
    std::vector<std::string> defines; // e.g. "TRANSLUCENT_PASS", "MAX_LIGHTS 4"
    bool operator<(const ProgramKey& other) const;
};

// Builds a program; throws std::runtime_error carrying the GL log with glsl/
// file names and lines when compiling or linking fails.
unsigned build_program(const GlApi& gl, const ProgramKey& key);

class ProgramCache {
public:
    explicit ProgramCache(const GlApi& gl) : gl_(gl) {}
    ~ProgramCache();
    ProgramCache(const ProgramCache&) = delete;
    ProgramCache& operator=(const ProgramCache&) = delete;

    unsigned get(const ProgramKey& key);
    std::size_t size() const { return programs_.size(); }

private:
    const GlApi& gl_;
    std::map<ProgramKey, unsigned> programs_;
};

}  // namespace m3055
