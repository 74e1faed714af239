#include "model_file/model.h"

#include "model_file/gltf_file.h"
#include "model_file/obj_file.h"
#include "model_file/vertex_normals.h"

#include <algorithm>
#include <cctype>

namespace m3055::model_file {

Format format_of(const std::string& file_name) {
    const std::size_t dot = file_name.find_last_of('.');
    std::string extension = dot == std::string::npos ? "" : file_name.substr(dot + 1);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == "obj") return Format::obj;
    if (extension == "gltf") return Format::gltf;
    if (extension == "glb") return Format::glb;
    throw ModelError("is not a model file this program reads: its name must end in .obj, .gltf or .glb");
}

Model parse_model(const std::string& bytes, Format format, const SideFileReader& side_files,
                  std::size_t max_triangles) {
    Soup soup = format == Format::obj ? parse_obj(bytes, side_files, max_triangles)
                                      : parse_gltf(bytes, format == Format::glb, side_files, max_triangles);
    return finish_model(std::move(soup));
}

}  // namespace m3055::model_file
