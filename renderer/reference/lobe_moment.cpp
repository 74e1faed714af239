#include "reference/lobe_moment.h"

#include "numeric/angles.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace m3055::ref {

namespace {

using numeric::kPi;

// Two planes through the origin are one great circle when their normals are this close to parallel.
constexpr double kSameCircle = 1e-12;

// A unit vector perpendicular to unit n.
dvec3 perpendicular(const dvec3& n) {
    return glm::normalize(std::fabs(n.x) > 0.5 ? glm::cross(n, dvec3(0, 1, 0)) : glm::cross(n, dvec3(1, 0, 0)));
}

// One arc of the region's boundary: angles [lo, hi] along the great circle of
// inward normal m, u(t) = cos t e1 + sin t e2 with e2 = m x e1 (moving along it
// keeps the region on the left); empty where hi <= lo.
struct CircleArc {
    dvec3 e1, e2;
    double lo, hi;
    dvec3 at(double t) const { return std::cos(t) * e1 + std::sin(t) * e2; }
};

// The part of the great circle of `planes[k]` inside every other plane's
// hemisphere: each is a half circle, [c - pi/2, c + pi/2] about the angle c of
// the plane's normal in the circle's frame; half circles meet in one arc.
CircleArc arc_on_circle(const std::vector<dvec3>& planes, std::size_t k) {
    const dvec3& m = planes[k];
    CircleArc arc;
    arc.e1 = perpendicular(m);
    arc.e2 = glm::cross(m, arc.e1);
    bool whole = true;
    for (std::size_t j = 0; j < planes.size(); ++j) {
        if (j == k) continue;
        const double a = glm::dot(planes[j], arc.e1), b = glm::dot(planes[j], arc.e2);
        if (std::hypot(a, b) < kSameCircle) continue;  // the same circle (an opposite one: no region at all, below)
        double c = std::atan2(b, a);
        if (whole) {
            arc.lo = c - 0.5 * kPi, arc.hi = c + 0.5 * kPi, whole = false;
            continue;
        }
        c -= 2.0 * kPi * std::floor((c - 0.5 * (arc.lo + arc.hi)) / (2.0 * kPi) + 0.5);
        arc.lo = std::max(arc.lo, c - 0.5 * kPi);
        arc.hi = std::min(arc.hi, c + 0.5 * kPi);
    }
    if (whole) arc.lo = 0.0, arc.hi = 2.0 * kPi;
    return arc;
}

// The signed solid angle of the spherical triangle (pole, a, b) (Van Oosterom and Strackee 1983).
double triangle_solid_angle(const dvec3& pole, const dvec3& a, const dvec3& b) {
    return 2.0 * std::atan2(glm::dot(pole, glm::cross(a, b)), 1.0 + glm::dot(pole, a) + glm::dot(pole, b) + glm::dot(a, b));
}

}  // namespace

double lobe_integral_in_hemispheres(const std::vector<dvec3>& planes, const dvec3& pole, const dvec3& axis, int n) {
    if (n < 1) return 0.0;
    for (std::size_t k = 0; k < planes.size(); ++k)
        for (std::size_t j = 0; j < k; ++j)
            if (glm::length(glm::cross(planes[j], planes[k])) < kSameCircle && glm::dot(planes[j], planes[k]) < 0.0)
                return 0.0;  // two opposite hemispheres: no area
    // I_n = (I_0 [n even] + sum over the boundary's arcs of (axis . m) sum_{j = n-1, n-3, ... >= 0} F_j) / (n + 1),
    // from the sphere's Laplacian of (axis . u)^k integrated over the region and Green's theorem on
    // its boundary, I_k = (k - 1) / (k + 1) I_{k-2} + 1 / (k + 1) sum (axis . m) F_{k-1}, whose
    // factors telescope; along an arc f(t) = axis . u(t), F_j = integral of f^j
    // = ((j - 1) |axis in the arc's plane|^2 F_{j-2} - [f^{j-1} f']) / j, F_0 = its length.
    const bool odd = n % 2 == 1;
    double sum = 0.0;
    for (std::size_t k = 0; k < planes.size(); ++k) {
        bool repeated = false;
        for (std::size_t j = 0; j < k; ++j)
            repeated = repeated || glm::length(glm::cross(planes[j], planes[k])) < kSameCircle;
        if (repeated) continue;
        const CircleArc arc = arc_on_circle(planes, k);
        if (arc.hi <= arc.lo) continue;
        const dvec3& m = planes[k];
        const double length = arc.hi - arc.lo;
        const dvec3 a = arc.at(arc.lo), b = arc.at(arc.hi);
        const double f0 = glm::dot(axis, a), df0 = glm::dot(axis, glm::cross(m, a));
        const double f1 = glm::dot(axis, b), df1 = glm::dot(axis, glm::cross(m, b));
        const double c2 = f0 * f0 + df0 * df0;
        double F = odd ? length : f0 * std::sin(length) + df0 * (1.0 - std::cos(length));  // F_0 or F_1
        double edge_sum = F;
        for (int j = odd ? 2 : 3; j < n; j += 2) {
            F = ((j - 1.0) * c2 * F - (std::pow(f1, j - 1) * df1 - std::pow(f0, j - 1) * df0)) / j;
            edge_sum += F;
        }
        sum += glm::dot(axis, m) * edge_sum;
        if (!odd)  // I_0, the region's solid angle: a fan of triangles from the pole, a quarter of the arc each at most
            for (int piece = 0; piece < 4; ++piece)
                sum += triangle_solid_angle(pole, arc.at(arc.lo + length * piece / 4.0),
                                            arc.at(arc.lo + length * (piece + 1) / 4.0));
    }
    return sum / (n + 1);
}

double clipped_lobe_integral(const std::vector<dvec3>& corners, const dvec3& inside, const dvec3& N,
                             const dvec3& axis, int n) {
    if (corners.size() < 3) return 0.0;
    // A convex polygon within a hemisphere is where every edge's plane has it on its inner side.
    const double winding = glm::dot(glm::cross(corners[0], corners[1]), inside) >= 0.0 ? 1.0 : -1.0;
    std::vector<dvec3> planes;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const dvec3 normal = glm::cross(corners[i], corners[(i + 1) % corners.size()]);
        if (glm::length(normal) > kSameCircle * glm::length(corners[i]) * glm::length(corners[(i + 1) % corners.size()]))
            planes.push_back(winding * glm::normalize(normal));
    }
    planes.push_back(N);
    planes.push_back(axis);
    return lobe_integral_in_hemispheres(planes, N, axis, n);
}

std::optional<double> disk_lobe_integral(const dvec3& c, const dvec3& e0, const dvec3& e1, const dvec3& N,
                                         const dvec3& axis, int n, int nodes) {
    auto rim_above = [&](const dvec3& m) {
        return glm::dot(m, c) > std::hypot(glm::dot(m, e0), glm::dot(m, e1));
    };
    if (n < 1 || !rim_above(N) || !rim_above(axis)) return std::nullopt;
    // (n + 1) I_n = I_0 [n even] + the rim's integral of (sum_{j = n-1, n-3, ... >= 0} f^j) axis . (u x u'),
    // f = axis . u, u x u' = (r x r') / |r|^2 (Green's theorem on the sphere, the conormal u x u' / |u'|);
    // I_0, the solid angle, as the rim's integral of the vector potential (pole x u) / (1 + pole . u),
    // singular only at -pole, behind the disk.
    const dvec3 pole = glm::normalize(c);
    const bool odd = n % 2 == 1;
    double solid = 0.0, boundary = 0.0;
    for (int k = 0; k < nodes; ++k) {
        const double t = 2.0 * kPi * k / nodes;
        const dvec3 r = c + std::cos(t) * e0 + std::sin(t) * e1, dr = -std::sin(t) * e0 + std::cos(t) * e1;
        const double r2 = glm::dot(r, r), length = std::sqrt(r2);
        const dvec3 u = r / length, du = (dr - glm::dot(u, dr) * u) / length;
        const double f = glm::dot(axis, u);
        double power = odd ? 1.0 : f, powers = 0.0;
        for (int j = odd ? 0 : 1; j < n; j += 2, power *= f * f) powers += power;
        boundary += powers * glm::dot(axis, glm::cross(r, dr)) / r2;
        solid += glm::dot(glm::cross(pole, u), du) / (1.0 + glm::dot(pole, u));
    }
    const double turn = solid >= 0.0 ? 1.0 : -1.0;  // the rim's orientation that makes the solid angle positive
    return turn * ((odd ? 0.0 : solid) + boundary) * (2.0 * kPi / nodes) / (n + 1);
}

std::vector<dvec3> hemisphere_corners(const dvec3& up) {
    const dvec3 t = perpendicular(up);
    const dvec3 b = glm::cross(up, t);
    return {t, b, -t, -b};
}

}  // namespace m3055::ref
