// What `m3055 bench` measured, and the writers of bench.md and bench.csv (the plot: plot.h).
#pragma once

#include "error_stats.h"
#include "timing.h"

#include <string>
#include <vector>

namespace m3055::bench {

// One way of rendering: its time per frame at two sizes and its error.
struct WayResult {
    std::string group;          // "geometry", "cheap metal", "shaders", "reference"
    std::string way;            // full name, for the table
    std::string label;          // short name, for the plot (and the csv's last column)
    std::string scenes;         // the scene set the times and errors are over
    std::string error_against;  // what the error is measured against
    TimeStats small, large;     // 512 x 320 and 1920 x 1080 frame times
    ErrorStats error;           // at 512 x 320
    bool exact_reference = false;  // the reference itself: error 0 by definition
};

// First frame (compile + draw) and steady frame, specialized vs general programs.
struct SpecializationResult {
    std::string scene;
    TimeStats first_specialized, first_general, steady_specialized, steady_general;
};

struct ProcessResult {
    TimeStats cold, warm;  // one `m3055 render` process; cold: MESA_SHADER_CACHE_DISABLE=true
    int batch_scenes = 0;
    double batch_ms = 0;     // one `m3055 batch` process over batch_scenes scenes
    double separate_ms = 0;  // batch_scenes `m3055 render` processes, one after another
    double ratio() const { return batch_ms > 0 ? separate_ms / batch_ms : 0.0; }
};

struct BenchResults {
    std::string device;  // GL_RENDERER and backend
    bool quick = false;
    int warm_up = 0, repetitions = 0, large_repetitions = 0;
    std::vector<WayResult> ways;
    std::vector<SpecializationResult> specialization;
    ProcessResult process;
    double total_seconds = 0;
    std::string load_before, load_after;  // /proc/loadavg: other work on the machine skews times
};

std::string markdown_report(const BenchResults& results);
std::string csv_report(const BenchResults& results);

}  // namespace m3055::bench
