// `m3055 bench`: run time against error (issue 4, part 1).
#pragma once

#include "gl/context.h"

#include <string>

namespace m3055::bench {

struct BenchOptions {
    std::string out = "bench";  // folder for bench.md, bench.csv, bench.png
    std::string scenes;         // folder with the paper's scenes; "" = find scenes/ (see find_scenes_dir)
    bool quick = false;         // few repetitions, small batch, no 1920 x 1080: a smoke run
    Backend backend = Backend::automatic;
};

// ./scenes, then scenes/ beside the executable's folder (build/../scenes).
std::string find_scenes_dir(const std::string& requested);

// Runs everything, writes the three files, and prints progress and the
// Markdown table to stdout. Throws std::runtime_error on failure.
void run_bench(const BenchOptions& options);

}  // namespace m3055::bench
