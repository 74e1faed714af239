// From a parser's triangles (polygon_soup.h) to a Model: numbers checked,
// degenerate triangles dropped, the file's normals normalized and, where it
// gives none, smooth angle-weighted normals across every edge whose faces
// meet at less than kCreaseAngleDeg (model_limits.h), a crease beyond it;
// one vertex per position, normal and group; the smooth parts; the box.
#pragma once

#include "model_file/polygon_soup.h"

namespace m3055::model_file {

Model finish_model(Soup soup);

}  // namespace m3055::model_file
