// `m3055 bench --area-latency`: the explorer's frame while a slider drags an
// area light (scenes/softbox_three_point.json, the key's width, 512 x 320):
// each step timed from the edit to finished pixels as the explorer draws it
// (render_displays + glFinish), and then the render's pixels the display
// refines to when the input stops.
#pragma once

#include "bench.h"

#include <string>

namespace m3055::bench {

struct DragStats {
    int steps = 0;
    double p50_ms = 0, p95_ms = 0, max_ms = 0;
};

struct AreaLatencyReport {
    std::string device;
    DragStats before;  // every frame at the display's size with 2 x 2 shadow rays (the explorer until now)
    DragStats after;   // the explorer's preview (explore/display_renderers.h)
    int divisor_min = 1, divisor_max = 1;  // the preview's sizes, 1/divisor of the display's
    double sharpen_ms = 0;                 // the refine's first pass: the preview at the display's size
    double refine_ms = 0;                  // from the last step to the render's pixels
    std::string markdown() const;
};

AreaLatencyReport area_light_latency(const BenchOptions& options);

// Runs it, prints the table and writes --out/area_latency.md.
void run_area_latency(const BenchOptions& options);

}  // namespace m3055::bench
