#include "model_file/obj_file.h"

#include "model_file/memory_stream.h"
#include "model_file/triangulate.h"

#define TINYOBJLOADER_IMPLEMENTATION  // compiled here, from Debian's header, for the desktop and the browser alike
#define TINYOBJLOADER_USE_DOUBLE
#include <tiny_obj_loader.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>

namespace m3055::model_file {

namespace {

// Ear tests allowed over a whole file: far more than any real model needs
// (a 1000-corner face takes about 10^6), few enough to end quickly.
constexpr std::size_t kMaxTriangulationWork = std::size_t(1) << 28;

// Lines starting with `f`, `v` and `vn`, counted before tinyobjloader builds
// its per-face structures, so a file of millions of tiny faces is refused
// from its counts rather than parsed into gigabytes.
// Also where a `v` or `vn` line holds anything but decimal numbers:
// tinyobjloader reads "nan", "inf" or a word as 0 without a word, so such a
// coordinate is refused here (1e400, which it reads as infinite, is refused
// with the other non-finite numbers in vertex_normals.cpp).
struct LineCounts {
    std::size_t faces = 0, vertices = 0;
    std::size_t first_bad_number_line = 0;  // 1-based; 0: none
};

bool number_character(char c) {
    return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.' || c == 'e' || c == 'E' || c == ' ' ||
           c == '\t' || c == '\r';
}

LineCounts count_lines(const std::string& bytes) {
    LineCounts counts;
    std::size_t i = 0, line = 0;
    const std::size_t n = bytes.size();
    while (i < n) {
        ++line;
        while (i < n && (bytes[i] == ' ' || bytes[i] == '\t')) ++i;
        const void* end = std::memchr(bytes.data() + i, '\n', n - i);
        const std::size_t stop = end ? std::size_t(static_cast<const char*>(end) - bytes.data()) : n;
        if (i + 1 < n && bytes[i] == 'f' && (bytes[i + 1] == ' ' || bytes[i + 1] == '\t')) ++counts.faces;
        const bool position = i + 1 < n && bytes[i] == 'v' && (bytes[i + 1] == ' ' || bytes[i + 1] == '\t');
        const bool normal = i + 2 < n && bytes[i] == 'v' && bytes[i + 1] == 'n' &&
                            (bytes[i + 2] == ' ' || bytes[i + 2] == '\t');
        if (position || normal) {
            ++counts.vertices;
            if (!counts.first_bad_number_line)
                for (std::size_t k = i + (normal ? 2 : 1); k < stop; ++k)
                    if (!number_character(bytes[k])) {
                        counts.first_bad_number_line = line;
                        break;
                    }
        }
        i = end ? stop + 1 : n;
    }
    return counts;
}

// .mtl files through the scene's confined, bounded reads.
class SideMaterials : public tinyobj::MaterialReader {
public:
    explicit SideMaterials(const SideFileReader& read) : read_(read) {}
    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* names, std::string* warn, std::string*) override {
        const std::string bytes = read_(name);  // throws ModelError
        MemoryStream stream(bytes);
        tinyobj::LoadMtl(names, materials, &stream, warn, nullptr);
        return true;
    }

private:
    const SideFileReader& read_;
};

bool has_texture(const tinyobj::material_t& m) {
    return !m.diffuse_texname.empty() || !m.specular_texname.empty() || !m.bump_texname.empty() ||
           !m.ambient_texname.empty() || !m.normal_texname.empty() || !m.alpha_texname.empty() ||
           !m.specular_highlight_texname.empty() || !m.displacement_texname.empty();
}

FileMaterial file_material(const tinyobj::material_t& m) {
    FileMaterial out;
    out.kind = FileMaterial::Kind::obj;
    out.name = m.name;
    out.kd = {m.diffuse[0], m.diffuse[1], m.diffuse[2]};
    out.ks = {m.specular[0], m.specular[1], m.specular[2]};
    out.ns = m.shininess;
    return out;
}

std::string count_text(std::size_t n) { return std::to_string(n); }

// The 1-based line of the first face corner whose vertex (`normals`: normal)
// index is past the file's `total` (or before the first, counting back from
// a negative index), 0 when none: tinyobjloader keeps no line numbers, so a
// bad index is found again this way, on the error's path only.
std::size_t line_of_bad_index(const std::string& bytes, bool normals, std::size_t total) {
    std::istringstream in(bytes);
    std::string text;
    std::int64_t seen = 0;  // vertices (or normals) defined so far: a negative index counts back from here
    for (std::size_t line = 1; std::getline(in, text); ++line) {
        std::istringstream words(text);
        std::string key;
        words >> key;
        if (key == (normals ? "vn" : "v")) ++seen;
        if (key != "f") continue;
        for (std::string corner; words >> corner;) {
            std::string field = corner;
            if (normals) {  // v/vt/vn or v//vn: the third field
                field = std::count(corner.begin(), corner.end(), '/') == 2 ? corner.substr(corner.rfind('/') + 1) : "";
            } else {
                field = corner.substr(0, corner.find('/'));
            }
            if (field.empty()) continue;
            char* end = nullptr;
            const long long index = std::strtoll(field.c_str(), &end, 10);
            const long long resolved = index < 0 ? seen + index + 1 : index;
            if (resolved < 1 || resolved > static_cast<long long>(total)) return line;
        }
    }
    return 0;
}

std::string at_line(std::size_t line) { return line ? "line " + std::to_string(line) + ": " : ""; }

}  // namespace

Soup parse_obj(const std::string& bytes, const SideFileReader& side_files, std::size_t max_triangles) {
    const LineCounts counts = count_lines(bytes);
    if (counts.faces > max_triangles)
        throw ModelError("has " + count_text(counts.faces) + " faces, more than the " + count_text(max_triangles) +
                         " triangles a scene may have");
    if (counts.vertices > 3 * max_triangles)
        throw ModelError("has " + count_text(counts.vertices) + " vertex lines, more than three for each of the " +
                         count_text(max_triangles) + " triangles a scene may have");

    if (counts.first_bad_number_line)
        throw ModelError("line " + count_text(counts.first_bad_number_line) +
                         ": a vertex or normal coordinate is not a finite number (NaN, Inf or not a number)");

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
    SideMaterials mtl(side_files);
    MemoryStream stream(bytes);
    // Not triangulated by tinyobjloader: it skips faces with bad indices, and
    // its own triangulation is not made for concave faces.
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &stream, &mtl, false, false)) {
        // tinyobjloader's message may quote the file: only the line number is kept.
        const std::size_t line = err.find("line ");
        std::string where;
        if (line != std::string::npos) {
            std::size_t end = line + 5;
            while (end < err.size() && std::isdigit(static_cast<unsigned char>(err[end]))) ++end;
            where = " (" + err.substr(line, end - line) + ")";
        }
        throw ModelError("is not a valid OBJ file: a face, line or point has a bad index" + where);
    }

    Soup soup;
    const std::size_t n_positions = attrib.vertices.size() / 3, n_normals = attrib.normals.size() / 3;
    soup.positions.reserve(n_positions);
    for (std::size_t i = 0; i < n_positions; ++i)
        soup.positions.push_back({attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]});
    std::vector<double>().swap(attrib.vertices);
    soup.normals.reserve(n_normals);
    for (std::size_t i = 0; i < n_normals; ++i)
        soup.normals.push_back({attrib.normals[3 * i], attrib.normals[3 * i + 1], attrib.normals[3 * i + 2]});
    std::vector<double>().swap(attrib.normals);

    // Groups: the file's materials in the order faces first use them; faces
    // without one (or naming one no .mtl defines) in a group of their own.
    std::map<int, std::uint32_t> group_of;
    bool textures = false, lines_or_points = false;
    std::size_t work = 0;
    std::vector<dvec3> polygon;
    for (const tinyobj::shape_t& shape : shapes) {
        if (!shape.lines.indices.empty() || !shape.points.indices.empty()) lines_or_points = true;
        const tinyobj::mesh_t& mesh = shape.mesh;
        std::size_t next = 0;
        for (std::size_t f = 0; f < mesh.num_face_vertices.size(); ++f) {
            const std::size_t n = mesh.num_face_vertices[f];
            if (next + n > mesh.indices.size()) throw ModelError("is not a valid OBJ file: a face is cut short");
            const int material = f < mesh.material_ids.size() ? mesh.material_ids[f] : -1;
            const int known = material >= 0 && std::size_t(material) < materials.size() ? material : -1;
            std::vector<Corner> corners;
            for (std::size_t k = 0; k < n; ++k) {
                const tinyobj::index_t& index = mesh.indices[next + k];
                if (index.vertex_index < 0 || std::size_t(index.vertex_index) >= n_positions)
                    throw ModelError(at_line(line_of_bad_index(bytes, false, n_positions)) + "a face names vertex " +
                                     std::to_string(std::int64_t(index.vertex_index) + 1) + ", but the file has " +
                                     count_text(n_positions) + " vertices");
                if (index.normal_index >= 0 && std::size_t(index.normal_index) >= n_normals)
                    throw ModelError(at_line(line_of_bad_index(bytes, true, n_normals)) + "a face names normal " +
                                     std::to_string(std::int64_t(index.normal_index) + 1) + ", but the file has " +
                                     count_text(n_normals) + " normals");
                corners.push_back({std::uint32_t(index.vertex_index), index.normal_index});
            }
            next += n;
            if (n < 3) continue;
            auto [found, added] = group_of.emplace(known, std::uint32_t(soup.materials.size()));
            if (added) {
                soup.materials.push_back(known >= 0 ? file_material(materials[std::size_t(known)]) : FileMaterial{});
                if (known >= 0 && has_texture(materials[std::size_t(known)])) textures = true;
            }
            polygon.clear();
            for (const Corner& c : corners) polygon.push_back(soup.positions[c.position]);
            for (const auto& t : triangulate_polygon(polygon, work)) {
                for (std::size_t k : t) soup.corners.push_back(corners[k]);
                soup.groups.push_back(found->second);
            }
            if (soup.groups.size() > max_triangles)
                throw ModelError("has more than the " + count_text(max_triangles) + " triangles a scene may have");
            if (work > kMaxTriangulationWork)
                throw ModelError("has polygons too large to triangulate (faces of thousands of corners)");
        }
    }
    if (soup.groups.empty())
        throw ModelError(lines_or_points ? "holds no triangles, only lines or points"
                                         : "holds no triangles (no faces: not an OBJ model, or an empty one)");
    if (textures) soup.notes.push_back("its textures are ignored: each material's colours are used");
    return soup;
}

}  // namespace m3055::model_file
