// The measured metals' data files, data/conductors/NAME.nk, embedded into the
// binary at build time (cmake/embed_files.cmake), sorted by name.
#pragma once

#include <vector>

namespace m3055::spectral {

struct ConductorFile {
    const char* name;  // the file's stem: "gold"
    const char* text;  // its whole text
};

const std::vector<ConductorFile>& conductor_files();

}  // namespace m3055::spectral
