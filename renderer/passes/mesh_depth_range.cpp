#include "passes/mesh_depth_range.h"

#include "passes/camera_frame.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <vector>

namespace m3055 {

namespace {

// Sutherland-Hodgman: keeps the part of `polygon` where dot(plane, (x, y, z, 1)) >= 0.
std::vector<dvec3> clip(const std::vector<dvec3>& polygon, const glm::dvec4& plane) {
    std::vector<dvec3> out;
    auto side = [&](const dvec3& p) { return plane.x * p.x + plane.y * p.y + plane.z * p.z + plane.w; };
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const dvec3& a = polygon[i];
        const dvec3& b = polygon[(i + 1) % polygon.size()];
        const double sa = side(a), sb = side(b);
        if (sa >= 0) out.push_back(a);
        if ((sa >= 0) != (sb >= 0)) out.push_back(a + (sa / (sa - sb)) * (b - a));
    }
    return out;
}

}  // namespace

std::optional<std::pair<double, double>> visible_depth_range(const CameraFrame& frame, const geometry::Mesh& mesh) {
    const double ex = frame.extent_x, ey = frame.extent_y;
    // x <= ex z, -x <= ex z, y <= ey z, -y <= ey z, z >= 0 (camera space: r, u_cam, f).
    const glm::dvec4 planes[] = {{-1, 0, ex, 0}, {1, 0, ex, 0}, {0, -1, ey, 0}, {0, 1, ey, 0}, {0, 0, 1, 0}};
    double z_min = 1e300, z_max = -1e300;
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        std::vector<dvec3> polygon;
        for (int k = 0; k < 3; ++k) {
            const dvec3 d = mesh.positions[mesh.indices[i + k]] - frame.position;
            polygon.push_back({glm::dot(d, frame.right), glm::dot(d, frame.up), glm::dot(d, frame.forward)});
        }
        for (const glm::dvec4& plane : planes) {
            polygon = clip(polygon, plane);
            if (polygon.empty()) break;
        }
        for (const dvec3& p : polygon) z_min = std::min(z_min, p.z), z_max = std::max(z_max, p.z);
    }
    if (z_min > z_max) return std::nullopt;
    return std::make_pair(z_min, z_max);
}

}  // namespace m3055
