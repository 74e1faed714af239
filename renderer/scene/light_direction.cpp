#include "scene/light_direction.h"

#include "numeric/angles.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace m3055 {

namespace {
using numeric::kPi;
using numeric::kDegree;
// Below this projected length the azimuth is numerically meaningless.
constexpr double kPoleEpsilon = 1e-9;
}  // namespace

dvec3 direction_from_angles(const Angles& angles) {
    const double a = angles.azimuth_deg * kDegree, e = angles.elevation_deg * kDegree;
    return {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
}

Angles angles_from_direction(const dvec3& direction, double previous_azimuth_deg) {
    const dvec3 d = glm::normalize(direction);
    Angles angles;
    angles.elevation_deg = std::asin(std::clamp(d.y, -1.0, 1.0)) / kDegree;
    const double horizontal = std::hypot(d.x, d.z);
    angles.azimuth_deg =
        horizontal < kPoleEpsilon ? previous_azimuth_deg : std::atan2(d.x, d.z) / kDegree;
    return angles;
}

dvec3 direction_from_disc(const DiscPoint& point) {
    const double r = std::hypot(point.x, point.y);
    if (r < kPoleEpsilon) return {0.0, 0.0, 1.0};
    const double ux = point.x / r, uy = point.y / r;  // unit direction in the disc
    if (r <= 1.0) return {point.x, point.y, std::sqrt(std::max(0.0, 1.0 - r * r))};
    // Back hemisphere: projected length shrinks from 1 at the rim to 0 at the ring's edge.
    const double projected = std::max(0.0, 1.0 - (r - 1.0) / kBackRing);
    return {ux * projected, uy * projected, -std::sqrt(std::max(0.0, 1.0 - projected * projected))};
}

DiscPoint disc_from_direction(const dvec3& direction) {
    const dvec3 d = glm::normalize(direction);
    const double projected = std::min(1.0, std::hypot(d.x, d.y));
    if (d.z >= 0.0) {
        // On the rim rounding can give a length just above 1, which would read back
        // as the back ring: keep front points inside the disc.
        const double length = std::hypot(d.x, d.y);
        return length > 1.0 ? DiscPoint{d.x / length, d.y / length} : DiscPoint{d.x, d.y};
    }
    // Straight behind: any angle is right; put it at the bottom of the ring.
    if (projected < kPoleEpsilon) return {0.0, -(1.0 + kBackRing)};
    const double r = 1.0 + (1.0 - projected) * kBackRing;
    return {d.x / projected * r, d.y / projected * r};
}

}  // namespace m3055
