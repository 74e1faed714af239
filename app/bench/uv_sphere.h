// A UV sphere (latitude/longitude grid) on the unit sphere, for the benchmark's
// tessellated-sphere ways.
#pragma once

#include <cstdint>
#include <vector>

namespace m3055::bench {

struct UvSphere {
    std::vector<float> positions;       // xyz per vertex, unit length (= the normal)
    std::vector<std::uint32_t> indices; // triangles, counter-clockwise seen from outside
    int triangles() const { return int(indices.size() / 3); }
};

// `slices` around the axis (>= 3), `stacks` from pole to pole (>= 2). Quads
// touching a pole become one triangle, so there are 2 * slices * (stacks - 1).
UvSphere make_uv_sphere(int slices, int stacks);

}  // namespace m3055::bench
