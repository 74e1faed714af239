// Wavefront OBJ (and its .mtl files, read through the SideFileReader) to
// triangles: tinyobjloader parses, every index is checked here, and polygons
// are triangulated by triangulate.h (concave ones too).
#pragma once

#include "model_file/polygon_soup.h"

namespace m3055::model_file {

Soup parse_obj(const std::string& bytes, const SideFileReader& side_files, std::size_t max_triangles);

}  // namespace m3055::model_file
