#include "model_bench_files.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace m3055::bench {

void write_bench_obj(const UvSphere& sphere, const std::string& path) {
    std::FILE* out = std::fopen(path.c_str(), "w");
    if (!out) throw std::runtime_error("cannot write " + path);
    for (std::size_t i = 0; i + 2 < sphere.positions.size(); i += 3)
        std::fprintf(out, "v %.6f %.6f %.6f\n", sphere.positions[i], sphere.positions[i + 1], sphere.positions[i + 2]);
    for (std::size_t i = 0; i + 2 < sphere.indices.size(); i += 3)
        std::fprintf(out, "f %u %u %u\n", sphere.indices[i] + 1, sphere.indices[i + 1] + 1, sphere.indices[i + 2] + 1);
    if (std::fclose(out) != 0) throw std::runtime_error("cannot write " + path);
}

namespace {

void put_u32(std::string& out, std::uint32_t v) {
    char bytes[4];
    std::memcpy(bytes, &v, 4);  // little-endian hosts only, as the .glb is
    out.append(bytes, 4);
}

}  // namespace

void write_bench_glb(const UvSphere& sphere, const std::string& path) {
    const std::size_t position_bytes = sphere.positions.size() * sizeof(float);
    const std::size_t index_bytes = sphere.indices.size() * sizeof(std::uint32_t);
    std::string bin(reinterpret_cast<const char*>(sphere.positions.data()), position_bytes);
    bin.append(reinterpret_cast<const char*>(sphere.indices.data()), index_bytes);
    while (bin.size() % 4) bin.push_back('\0');
    using nlohmann::json;
    const json doc = {
        {"asset", {{"version", "2.0"}}},
        {"buffers", {{{"byteLength", bin.size()}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", position_bytes}, {"target", 34962}},
          {{"buffer", 0}, {"byteOffset", position_bytes}, {"byteLength", index_bytes}, {"target", 34963}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", sphere.positions.size() / 3}, {"type", "VEC3"},
           {"min", {-1, -1, -1}}, {"max", {1, 1, 1}}},
          {{"bufferView", 1}, {"componentType", 5125}, {"count", sphere.indices.size()}, {"type", "SCALAR"}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"scenes", {{{"nodes", {0}}}}},
        {"scene", 0},
    };
    std::string text = doc.dump();
    while (text.size() % 4) text.push_back(' ');
    std::string glb;
    put_u32(glb, 0x46546C67);  // "glTF"
    put_u32(glb, 2);
    put_u32(glb, std::uint32_t(12 + 8 + text.size() + 8 + bin.size()));
    put_u32(glb, std::uint32_t(text.size()));
    put_u32(glb, 0x4E4F534A);  // "JSON"
    glb += text;
    put_u32(glb, std::uint32_t(bin.size()));
    put_u32(glb, 0x004E4942);  // "BIN\0"
    glb += bin;
    std::ofstream out(path, std::ios::binary);
    out.write(glb.data(), std::streamsize(glb.size()));
    if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace m3055::bench
