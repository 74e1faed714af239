// The property the model-file fuzzer checks (tests/fuzz/model_fuzz.cpp),
// kept in a header so that ctest re-checks its seeds and any committed
// regression input in every build (tests/model_fuzz_regressions_test.cpp).
// An input is a model file: its first byte picks the format (0: OBJ, 1:
// .gltf, 2: .glb, modulo 3), and after a line "#side" the rest is the one
// file it may name (an OBJ's .mtl, a glTF's .bin) whatever its name.
// parse_model either returns triangles with finite unit normals, indices and
// groups in range and a box around the positions, or throws one ModelError
// line of valid UTF-8; never another exception.
#pragma once

#include "model_file/model.h"
#include "scene_fuzz_check.h"

#include <cmath>
#include <cstdint>
#include <string>

namespace m3055::fuzz {

// Few triangles keep one execution fast; the limit's own check is still fuzzed.
inline constexpr std::size_t kFuzzMaxTriangles = 20000;

inline std::string check_model(const model_file::Model& m) {
    if (m.normals.size() != m.positions.size()) return "a normal per position missing";
    if (m.indices.size() % 3 != 0 || m.groups.size() != m.triangles() || m.parts.size() != m.triangles())
        return "the triangles' lists disagree";
    if (m.triangles() == 0) return "a model without triangles was returned";
    for (std::uint32_t i : m.indices)
        if (i >= m.positions.size()) return "an index past the positions";
    for (std::uint32_t g : m.groups)
        if (g >= m.materials.size()) return "a group past the materials";
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const auto& p = m.positions[i];
        const auto& n = m.normals[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return "a non-finite position";
        const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
        if (!(std::abs(length - 1.0) < 1e-6)) return "a normal that is not unit";
        if (p.x < m.lo.x || p.y < m.lo.y || p.z < m.lo.z || p.x > m.hi.x || p.y > m.hi.y || p.z > m.hi.z)
            return "a position outside the box";
    }
    return "";
}

inline std::string check_model_input(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return "";
    const model_file::Format format = static_cast<model_file::Format>(data[0] % 3);
    std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1), side;
    const std::size_t marker = bytes.find("\n#side\n");
    if (marker != std::string::npos) {
        side = bytes.substr(marker + 7);
        bytes.resize(marker + 1);
    }
    const model_file::SideFileReader side_files = [&](const std::string&) { return side; };
    try {
        return check_model(model_file::parse_model(bytes, format, side_files, kFuzzMaxTriangles));
    } catch (const model_file::ModelError& e) {
        return check_error_message(e.what(), false);
    } catch (const std::exception& e) {
        return std::string("not a ModelError: ") + e.what();
    }
}

}  // namespace m3055::fuzz
