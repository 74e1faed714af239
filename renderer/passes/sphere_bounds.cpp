#include "passes/sphere_bounds.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace m3055 {
namespace {

struct SlopeRange {
    double lo, hi;
};

// Perspective: the rays x = s z through the origin that touch the circle of
// centre (x, z), radius r, in one coordinate plane of camera space. The
// u (or v) range of the sphere's image is exactly this range of slopes s.
std::optional<SlopeRange> tangent_slopes(double x, double z, double r) {
    const double d2 = x * x + z * z;
    if (d2 <= r * r) return SlopeRange{-1e30, 1e30};  // the eye is inside this cylinder
    const double centre = std::atan2(x, z), half = std::asin(r / std::sqrt(d2));
    const double lo = centre - half, hi = centre + half;
    if (lo >= M_PI / 2 || hi <= -M_PI / 2) return std::nullopt;  // wholly behind
    return SlopeRange{lo <= -M_PI / 2 ? -1e30 : std::tan(lo), hi >= M_PI / 2 ? 1e30 : std::tan(hi)};
}

}  // namespace

std::optional<std::array<float, 4>> sphere_ndc_rect(const CameraFrame& frame, const dvec3& center,
                                                    double radius) {
    const dvec3 c = center - frame.position;
    const double x = glm::dot(c, frame.right), y = glm::dot(c, frame.up), z = glm::dot(c, frame.forward);
    SlopeRange u{}, v{};
    if (frame.projection == Projection::perspective) {
        if (z + radius <= 0) return std::nullopt;
        auto su = tangent_slopes(x, z, radius), sv = tangent_slopes(y, z, radius);
        if (!su || !sv) return std::nullopt;
        u = {su->lo / frame.extent_x, su->hi / frame.extent_x};
        v = {sv->lo / frame.extent_y, sv->hi / frame.extent_y};
    } else {
        if (z + radius <= 0) return std::nullopt;
        u = {(x - radius) / frame.extent_x, (x + radius) / frame.extent_x};
        v = {(y - radius) / frame.extent_y, (y + radius) / frame.extent_y};
    }
    const double pad_x = 4.0 / frame.width, pad_y = 4.0 / frame.height;  // two pixels
    const double x0 = std::max(u.lo - pad_x, -1.0), x1 = std::min(u.hi + pad_x, 1.0);
    const double y0 = std::max(v.lo - pad_y, -1.0), y1 = std::min(v.hi + pad_y, 1.0);
    if (x0 >= x1 || y0 >= y1) return std::nullopt;
    return std::array<float, 4>{float(x0), float(y0), float(x1), float(y1)};
}

}  // namespace m3055
