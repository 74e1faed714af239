// Model files written by the tests from a mesh (geometry::Mesh), in each
// format the loader reads: OBJ (with normals, optionally a .mtl), glTF with
// its buffer embedded or beside it, and .glb. Coordinates and normals are
// written as given; tests that compare formats byte for byte give whole
// numbers (exact in float32 and in every decimal parser).
#pragma once

#include "geometry/mesh.h"

#include <string>

namespace m3055::test {

// `mtl`: the .mtl's name in the same folder, "" for none; each group g uses material "m<g>".
void write_obj(const geometry::Mesh& mesh, const std::string& path, bool normals = true, const std::string& mtl = "");
enum class GltfBuffer { embedded, side_file };
void write_gltf(const geometry::Mesh& mesh, const std::string& path, GltfBuffer buffer = GltfBuffer::embedded);
void write_glb(const geometry::Mesh& mesh, const std::string& path);

// A UV sphere of `slices` x `stacks` quads, radius `radius` around the
// origin, analytic normals; positions and normals rounded to whole numbers
// (normals scaled by `normal_scale` first), so each format holds them exactly.
geometry::Mesh integer_uv_sphere(int slices, int stacks, double radius, double normal_scale);

}  // namespace m3055::test
