// What a parser hands on: triangles whose corners index the file's positions
// and (optionally) its normals, one group a triangle. finish_model
// (vertex_normals.h) turns it into a Model.
#pragma once

#include "model_file/model.h"

#include <cstdint>
#include <vector>

namespace m3055::model_file {

struct Corner {
    std::uint32_t position;
    std::int64_t normal = -1;  // index into Soup::normals, -1: none given
};

struct Soup {
    std::vector<dvec3> positions;
    std::vector<dvec3> normals;
    std::vector<Corner> corners;          // 3 per triangle
    std::vector<std::uint32_t> groups;    // per triangle
    std::vector<FileMaterial> materials;  // one per group
    std::vector<std::string> notes;
};

}  // namespace m3055::model_file
