#include "reference/lobe_moment.h"

#include "numeric/angles.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace m3055::ref {

namespace {

using numeric::kPi;

// Which side of a plane through the origin the direction q lies on (0: on it, to rounding).
int side(double distance, const dvec3& q) {
    const double tolerance = 1e-12 * glm::length(q);
    return distance > tolerance ? 1 : distance < -tolerance ? -1 : 0;
}

// Sutherland-Hodgman: the part of convex `polygon` (directions, wound by `winding` about
// its inside: +1 counter-clockwise) where plane . u >= 0. The cut runs along the plane's
// great circle; where it spans more than a quarter circle (the sky's hemisphere cut by
// any plane: half a circle, its ends opposite), the corner a quarter along it is added,
// so that no edge is ambiguous.
std::vector<dvec3> clip_to_plane(const std::vector<dvec3>& polygon, const dvec3& plane, double winding) {
    std::vector<dvec3> kept;
    std::vector<bool> on_plane;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const dvec3& a = polygon[i];
        const dvec3& b = polygon[(i + 1) % polygon.size()];
        const double da = glm::dot(a, plane), db = glm::dot(b, plane);
        const int sa = side(da, a), sb = side(db, b);
        if (sa >= 0) kept.push_back(a), on_plane.push_back(sa == 0);
        if (sa * sb < 0) kept.push_back(a + (da / (da - db)) * (b - a)), on_plane.push_back(true);
    }
    std::vector<dvec3> out;
    for (std::size_t i = 0; i < kept.size(); ++i) {
        out.push_back(kept[i]);
        const std::size_t j = (i + 1) % kept.size();
        if (on_plane[i] && on_plane[j] && glm::dot(kept[i], kept[j]) < 0.0)
            out.push_back(winding * glm::cross(plane, glm::normalize(kept[i])));
    }
    return out;
}

// Unit corners, without those that repeat their predecessor (an edge of no length has no plane).
std::vector<dvec3> unit_corners(const std::vector<dvec3>& polygon) {
    std::vector<dvec3> unit;
    for (const dvec3& corner : polygon) {
        const dvec3 u = glm::normalize(corner);
        if (unit.empty() || glm::length(glm::cross(unit.back(), u)) > 1e-12) unit.push_back(u);
    }
    while (unit.size() > 1 && glm::length(glm::cross(unit.back(), unit.front())) <= 1e-12) unit.pop_back();
    return unit;
}

// One edge, the great arc from unit a to unit b: its length, its plane's unit
// normal m = a x b / |a x b|, and w . u along it, f(t) = w.a cos t + w.t0 sin t.
struct Arc {
    double length;
    dvec3 m;
    double f0, df0, f1, df1;  // f and f' at both ends
};

Arc arc(const dvec3& a, const dvec3& b, const dvec3& w) {
    const dvec3 axb = glm::cross(a, b);
    const double sine = glm::length(axb), cosine = glm::dot(a, b);
    Arc e;
    e.length = std::atan2(sine, cosine);
    e.m = axb / sine;
    const dvec3 t0 = glm::cross(e.m, a);  // the unit tangent at a, towards b
    const dvec3 t1 = glm::cross(e.m, b);  // and at b
    e.f0 = glm::dot(w, a), e.df0 = glm::dot(w, t0);
    e.f1 = glm::dot(w, b), e.df1 = glm::dot(w, t1);
    return e;
}

// The polygon's solid angle by Gauss-Bonnet: 2 pi less the turns of its edges' planes at the corners.
double solid_angle(const std::vector<Arc>& arcs) {
    double turns = 0.0;
    for (std::size_t i = 0; i < arcs.size(); ++i) {
        const dvec3& before = arcs[(i + arcs.size() - 1) % arcs.size()].m;
        turns += std::atan2(glm::length(glm::cross(before, arcs[i].m)), glm::dot(before, arcs[i].m));
    }
    return 2.0 * kPi - turns;
}

}  // namespace

double clipped_lobe_integral(const std::vector<dvec3>& corners, const dvec3& inside, const dvec3& N,
                             const dvec3& axis, int n) {
    if (corners.size() < 3 || n < 1) return 0.0;
    const double winding = glm::dot(glm::cross(corners[0], corners[1]), inside) >= 0.0 ? 1.0 : -1.0;
    const std::vector<dvec3> unit = unit_corners(clip_to_plane(clip_to_plane(corners, N, winding), axis, winding));
    if (unit.size() < 3) return 0.0;
    std::vector<Arc> arcs;
    for (std::size_t i = 0; i < unit.size(); ++i) arcs.push_back(arc(unit[i], unit[(i + 1) % unit.size()], axis));
    // Each edge's plane normal turned towards the inside.
    if (winding < 0.0)
        for (Arc& e : arcs) e.m = -e.m;
    // I_k = (k-1)/(k+1) I_{k-2} + 1/(k+1) sum_edges (w.m) F_{k-1}, from the sphere's Laplacian
    // of (w.u)^k integrated over the polygon and Green's theorem on its boundary; along an edge
    // F_j = integral of f^j = ((j-1) |w_plane|^2 F_{j-2} - [f^{j-1} f']) / j, F_0 = length
    // (f'' = -f, so (f^{j-1} f')' = (j-1) c^2 f^{j-2} - j f^j).
    std::vector<double> F(arcs.size());
    const bool odd = n % 2 == 1;
    double I = odd ? 0.0 : solid_angle(arcs);  // I_{-1} (unused: its weight is 0) or I_0
    for (std::size_t i = 0; i < arcs.size(); ++i) {
        const Arc& e = arcs[i];
        F[i] = odd ? e.length : e.f0 * std::sin(e.length) + e.df0 * (1.0 - std::cos(e.length));  // F_0 or F_1
    }
    for (int k = odd ? 1 : 2; k <= n; k += 2) {
        const int j = k - 1;  // F holds F_j
        if (j >= 2)
            for (std::size_t i = 0; i < arcs.size(); ++i) {
                const Arc& e = arcs[i];
                const double c2 = e.f0 * e.f0 + e.df0 * e.df0;
                F[i] = ((j - 1.0) * c2 * F[i] - (std::pow(e.f1, j - 1) * e.df1 - std::pow(e.f0, j - 1) * e.df0)) / j;
            }
        double boundary = 0.0;
        for (std::size_t i = 0; i < arcs.size(); ++i) boundary += glm::dot(axis, arcs[i].m) * F[i];
        I = (k - 1.0) / (k + 1.0) * I + boundary / (k + 1.0);
    }
    return I;
}

std::vector<dvec3> hemisphere_corners(const dvec3& up) {
    const dvec3 t = glm::normalize(std::fabs(up.x) > 0.5 ? glm::cross(up, dvec3(0, 1, 0)) : glm::cross(up, dvec3(1, 0, 0)));
    const dvec3 b = glm::cross(up, t);
    return {t, b, -t, -b};
}

}  // namespace m3055::ref
