// glTF 2.0 (.gltf with embedded or side buffers, .glb) to triangles:
// tinygltf parses, with no image decoding and no file access of its own
// (side .bin files through the SideFileReader); accessors, indices and
// extensions are checked here, and the scene's node transforms applied.
#pragma once

#include "model_file/polygon_soup.h"

namespace m3055::model_file {

Soup parse_gltf(const std::string& bytes, bool binary, const SideFileReader& side_files, std::size_t max_triangles);

}  // namespace m3055::model_file
