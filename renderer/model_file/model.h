// A student's model file (docs/shapes.md#meshes-from-files) as triangles in
// double, in the file's own coordinates: Wavefront OBJ through tinyobjloader,
// glTF 2.0 (.gltf, .glb) through tinygltf, both Debian's. Every file is
// untrusted: sizes, counts, indices and numbers are checked, and a problem is
// one ModelError line that never quotes the file's content.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace m3055::model_file {

using glm::dvec3;

// what(): the problem, without the file's name (the caller prefixes it).
class ModelError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A material as the file gives it: an OBJ .mtl's Kd, Ks, Ns, or a glTF
// pbrMetallicRoughness's base colour, metallic and roughness.
struct FileMaterial {
    enum class Kind { none, obj, gltf };
    Kind kind = Kind::none;
    std::string name;  // the file's name for it ("" when it has none)
    dvec3 kd{0.8}, ks{0.0};
    double ns = 0.0;
    dvec3 base_color{1.0};
    double metallic = 1.0, roughness = 1.0;  // glTF's defaults
};

// The triangles, counter-clockwise seen from their front (as both formats
// define it), with unit normals per vertex (the file's, or made as
// vertex_normals.h says). A vertex belongs to one group and one smooth part.
struct Model {
    std::vector<dvec3> positions;
    std::vector<dvec3> normals;          // unit, one per position
    std::vector<std::uint32_t> indices;  // 3 per triangle
    std::vector<std::uint32_t> groups;   // per triangle: its index in `materials`
    std::vector<std::uint32_t> parts;    // per triangle: its smooth piece (creases and groups part them)
    std::vector<FileMaterial> materials; // one per group, in the file's order
    dvec3 lo{0.0}, hi{0.0};              // the bounding box of the positions
    std::vector<std::string> notes;      // what was ignored (textures), one line each
    std::vector<std::string> side_files; // the files it named that were read (.mtl, .bin), as named, each once
    std::size_t triangles() const { return indices.size() / 3; }
};

// Reads a file the model names (an OBJ's .mtl, a glTF's .bin), relative to
// the model file's folder, under the scene's confinement; throws ModelError.
using SideFileReader = std::function<std::string(const std::string& name)>;

enum class Format { obj, gltf, glb };

// The format by the file name's extension (any case); throws ModelError for another.
Format format_of(const std::string& file_name);

// Parses `bytes` (the whole model file) with at most `max_triangles`.
Model parse_model(const std::string& bytes, Format format, const SideFileReader& side_files,
                  std::size_t max_triangles);

}  // namespace m3055::model_file
