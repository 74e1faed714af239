// `m3055 bench --area-lights`: run time against error of the area lights'
// sampling (passes/light_uniforms.h: AreaSampling) on the scenes that use
// them (scenes/softbox_three_point.json, sky_fill.json), each against the CPU
// reference: the explorer's fast preview, the render's setting and those
// between and beyond. Written to --out/area_lights.md and .csv, and printed.
#pragma once

#include "bench.h"

namespace m3055::bench {

void run_area_bench(const BenchOptions& options);

}  // namespace m3055::bench
