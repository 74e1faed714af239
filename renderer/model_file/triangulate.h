// Polygons with more than three corners (an OBJ face) as triangles, concave
// ones included: ear clipping in the polygon's own plane, the triangles
// keeping the polygon's winding.
#pragma once

#include "model_file/model.h"

#include <array>
#include <cstddef>
#include <vector>

namespace m3055::model_file {

// Triangles of the polygon `points` (corners in order), as index triples into
// `points`. A polygon with no ear left (self-intersecting, collinear) gives
// the rest as a fan. `work` counts the ear tests, so a caller can bound them.
std::vector<std::array<std::size_t, 3>> triangulate_polygon(const std::vector<dvec3>& points, std::size_t& work);

}  // namespace m3055::model_file
