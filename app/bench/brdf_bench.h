// `m3055 bench --brdf DIR`: a model from a .brdf file against the built-in model
// it copies (tests/data/brdf/: Lambert, Blinn-Phong, GGX + Schlick), steady
// frame time at 512 x 320 and 1920 x 1080 and first-frame (compile + draw)
// time, written as DIR_OUT/brdf.md and printed.
#pragma once

#include "bench.h"

namespace m3055::bench {

void run_brdf_bench(const BenchOptions& options, const std::string& brdf_dir);

}  // namespace m3055::bench
