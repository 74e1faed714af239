// The scenes/*.json files, embedded into the executable at build time by
// cmake/embed_files.cmake, so the figure presets work from any directory.
#pragma once

#include <string>
#include <vector>

namespace m3055::explore {

struct FigureScene {
    std::string name;  // file stem: "fig05", "spec_example"
    std::string json;  // the file's text
};

// Sorted by name.
const std::vector<FigureScene>& figure_scenes();

}  // namespace m3055::explore
