#include "model_writer.h"

#include "test_support.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace m3055::test {

namespace {

std::string number(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

// The mesh as glTF's binary buffer: positions, normals (float32), indices (uint32).
std::string buffer_bytes(const geometry::Mesh& mesh) {
    std::string bytes;
    auto put = [&](const void* data, std::size_t size) { bytes.append(static_cast<const char*>(data), size); };
    for (const dvec3& p : mesh.positions) {
        const float v[3] = {float(p.x), float(p.y), float(p.z)};
        put(v, sizeof v);
    }
    for (const dvec3& n : mesh.normals) {
        const float v[3] = {float(n.x), float(n.y), float(n.z)};
        put(v, sizeof v);
    }
    put(mesh.indices.data(), mesh.indices.size() * 4);
    return bytes;
}

std::string base64(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t v = std::uint32_t(std::uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) v |= std::uint32_t(std::uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) v |= std::uint8_t(bytes[i + 2]);
        out += digits[(v >> 18) & 63];
        out += digits[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[v & 63] : '=';
    }
    return out;
}

nlohmann::json gltf_json(const geometry::Mesh& mesh, const std::string& uri, std::size_t length) {
    using nlohmann::json;
    const std::size_t n = mesh.positions.size(), positions = n * 12, normals = n * 12;
    dvec3 lo(1e300), hi(-1e300);
    for (const dvec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    json buffer = json::object();
    buffer["byteLength"] = length;
    if (!uri.empty()) buffer["uri"] = uri;
    auto view = [](std::size_t offset, std::size_t size) {
        json v = json::object();
        v["buffer"] = 0, v["byteOffset"] = offset, v["byteLength"] = size;
        return v;
    };
    auto accessor = [](int view_index, int component, std::size_t count, const char* type) {
        json a = json::object();
        a["bufferView"] = view_index, a["componentType"] = component, a["count"] = count, a["type"] = type;
        return a;
    };
    json position = accessor(0, 5126, n, "VEC3");
    position["min"] = json::array({float(lo.x), float(lo.y), float(lo.z)});
    position["max"] = json::array({float(hi.x), float(hi.y), float(hi.z)});
    json attributes = json::object();
    attributes["POSITION"] = 0, attributes["NORMAL"] = 1;
    json primitive = json::object();
    primitive["attributes"] = attributes, primitive["indices"] = 2;
    json mesh_json = json::object();
    mesh_json["primitives"] = json::array({primitive});
    json node = json::object();
    node["mesh"] = 0;
    json scene = json::object();
    scene["nodes"] = json::array({0});
    json out = json::object();
    out["asset"] = json::object({{"version", "2.0"}});
    out["scene"] = 0;
    out["scenes"] = json::array({scene});
    out["nodes"] = json::array({node});
    out["meshes"] = json::array({mesh_json});
    out["buffers"] = json::array({buffer});
    out["bufferViews"] = json::array({view(0, positions), view(positions, normals),
                                      view(positions + normals, mesh.indices.size() * 4)});
    out["accessors"] = json::array({position, accessor(1, 5126, n, "VEC3"),
                                    accessor(2, 5125, mesh.indices.size(), "SCALAR")});
    return out;
}

}  // namespace


void write_obj(const geometry::Mesh& mesh, const std::string& path, bool normals, const std::string& mtl) {
    std::string text;
    if (!mtl.empty()) text += "mtllib " + mtl + "\n";
    for (const dvec3& p : mesh.positions) text += "v " + number(p.x) + " " + number(p.y) + " " + number(p.z) + "\n";
    if (normals)
        for (const dvec3& n : mesh.normals) text += "vn " + number(n.x) + " " + number(n.y) + " " + number(n.z) + "\n";
    std::uint32_t group = ~0u;
    for (std::size_t t = 0; t < mesh.triangles(); ++t) {
        const std::uint32_t g = mesh.groups.empty() ? 0 : mesh.groups[t];
        if (!mtl.empty() && g != group) text += "usemtl m" + std::to_string(g) + "\n";
        group = g;
        text += "f";
        for (int k = 0; k < 3; ++k) {
            const std::string i = std::to_string(mesh.indices[3 * t + k] + 1);
            text += " " + i + (normals ? "//" + i : "");
        }
        text += "\n";
    }
    write_text(path, text);
}

void write_gltf(const geometry::Mesh& mesh, const std::string& path, GltfBuffer buffer) {
    const std::string bytes = buffer_bytes(mesh);
    std::string uri;
    if (buffer == GltfBuffer::embedded) {
        uri = "data:application/octet-stream;base64," + base64(bytes);
    } else {
        const std::string bin = path.substr(0, path.find_last_of('.')) + ".bin";
        write_text(bin, bytes);
        uri = bin.substr(bin.find_last_of('/') + 1);
    }
    write_text(path, gltf_json(mesh, uri, bytes.size()).dump());
}

void write_glb(const geometry::Mesh& mesh, const std::string& path) {
    std::string bin = buffer_bytes(mesh);
    std::string json = gltf_json(mesh, "", bin.size()).dump();
    while (json.size() % 4) json += ' ';
    while (bin.size() % 4) bin += '\0';
    std::string out = "glTF";
    auto u32 = [&](std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    u32(2);
    u32(std::uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    u32(std::uint32_t(json.size()));
    u32(0x4E4F534A);  // "JSON"
    out += json;
    u32(std::uint32_t(bin.size()));
    u32(0x004E4942);  // "BIN\0"
    out += bin;
    write_text(path, out);
}

geometry::Mesh integer_uv_sphere(int slices, int stacks, double radius, double normal_scale) {
    const double pi = 3.14159265358979323846;
    geometry::Mesh mesh;
    for (int j = 0; j <= stacks; ++j) {
        const double theta = pi * j / stacks;
        for (int i = 0; i <= slices; ++i) {
            const double phi = 2 * pi * i / slices;
            const dvec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
            const dvec3 p = glm::round(n * radius);
            mesh.positions.push_back(p);
            mesh.normals.push_back(glm::round(glm::normalize(p) * normal_scale));
        }
    }
    auto at = [&](int i, int j) { return std::uint32_t(j * (slices + 1) + i); };
    for (int j = 0; j < stacks; ++j)
        for (int i = 0; i < slices; ++i) {
            // Counter-clockwise from outside; the poles' degenerate halves left out.
            if (j > 0) mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j)});
            if (j + 1 < stacks) mesh.indices.insert(mesh.indices.end(), {at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)});
        }
    mesh.parts.assign(mesh.triangles(), 0);
    return mesh;
}

}  // namespace m3055::test
