// The benchmark's model files, made at bench time (never committed): a UV
// sphere of about a million triangles without normals (so the load makes
// them, as for a file exported without), as a Wavefront OBJ and a .glb.
#pragma once

#include "uv_sphere.h"

#include <string>

namespace m3055::bench {

void write_bench_obj(const UvSphere& sphere, const std::string& path);
void write_bench_glb(const UvSphere& sphere, const std::string& path);

}  // namespace m3055::bench
