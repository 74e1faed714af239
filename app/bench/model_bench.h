// `m3055 bench --model-files`: a model file of about a million triangles
// (a UV sphere without normals, made at bench time as an OBJ and a .glb)
// loaded and shown at 512 x 320: the load's steps (read, parse, normals),
// the first frame (placing, building and uploading the mesh, drawing) and a
// frame after a camera move (the mesh pass's batch reused: its triangles per
// second). Written to --out/model_files.md and .csv, and printed.
#pragma once

#include "bench.h"

namespace m3055::bench {

void run_model_bench(const BenchOptions& options);

}  // namespace m3055::bench
