// `m3055 bench`: run time against error.
#pragma once

#include "gl/context.h"

#include <string>

namespace m3055::bench {

struct BenchOptions {
    std::string out = "bench";  // folder for bench.md, bench.csv, bench.gp, bench.png
    std::string scenes;         // folder with the paper's scenes; "" = find scenes/ (see find_scenes_dir)
    bool quick = false;         // few repetitions, small batch, no 1920 x 1080: a smoke run
    Backend backend = Backend::automatic;
    bool replot = false;        // measure nothing: redraw out/bench.png from out/bench.csv
    bool latency_only = false;  // only the explorer latency section (latency.md)
};

// ./scenes, then scenes/ beside the executable's folder (build/../scenes).
std::string find_scenes_dir(const std::string& requested);

// Runs everything, writes bench.md, bench.csv, bench.gp and (with gnuplot)
// bench.png, and prints progress and the Markdown table to stdout. Without
// gnuplot it says so in one line on stderr and still succeeds. Throws
// std::runtime_error on failure. With options.replot, only the plot files.
void run_bench(const BenchOptions& options);

}  // namespace m3055::bench
