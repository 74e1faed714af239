#include "model_file/triangulate.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace m3055::model_file {

namespace {

struct Point2 {
    double x, y;
};

double cross2(const Point2& o, const Point2& a, const Point2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Inside or on the counter-clockwise triangle abc.
bool inside(const Point2& p, const Point2& a, const Point2& b, const Point2& c) {
    return cross2(a, b, p) >= 0 && cross2(b, c, p) >= 0 && cross2(c, a, p) >= 0;
}

}  // namespace

std::vector<std::array<std::size_t, 3>> triangulate_polygon(const std::vector<dvec3>& points, std::size_t& work) {
    const std::size_t n = points.size();
    std::vector<std::array<std::size_t, 3>> out;
    if (n < 3) return out;
    if (n == 3) return {{0, 1, 2}};
    // Newell's normal: the polygon's orientation, robust for concave ones.
    dvec3 normal(0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const dvec3& a = points[i];
        const dvec3& b = points[(i + 1) % n];
        normal += dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    // Projected on the plane of the two other axes than the normal's largest,
    // flipped where needed so the polygon runs counter-clockwise there.
    const dvec3 m = glm::abs(normal);
    const int drop = m.x >= m.y && m.x >= m.z ? 0 : m.y >= m.z ? 1 : 2;
    const int u = (drop + 1) % 3, v = (drop + 2) % 3;
    const double flip = normal[drop] < 0 ? -1.0 : 1.0;
    std::vector<Point2> p(n);
    for (std::size_t i = 0; i < n; ++i) p[i] = {points[i][u], flip * points[i][v]};

    std::vector<std::size_t> left(n);
    for (std::size_t i = 0; i < n; ++i) left[i] = i;
    std::size_t at = 1, misses = 0;  // a convex polygon becomes the fan from its first corner
    while (left.size() > 3) {
        const std::size_t k = left.size();
        const std::size_t i0 = left[(at + k - 1) % k], i1 = left[at % k], i2 = left[(at + 1) % k];
        bool ear = cross2(p[i0], p[i1], p[i2]) > 0;  // convex corner
        for (std::size_t j = 0; ear && j < k; ++j) {
            const std::size_t q = left[j];
            ++work;
            if (q == i0 || q == i1 || q == i2) continue;
            if (inside(p[q], p[i0], p[i1], p[i2])) ear = false;
        }
        if (ear) {
            out.push_back({i0, i1, i2});
            left.erase(left.begin() + std::ptrdiff_t(at % k));
            misses = 0;
            continue;
        }
        at = (at + 1) % k;
        if (++misses > k) break;  // no ear: self-intersecting or degenerate
    }
    for (std::size_t j = 1; j + 1 < left.size(); ++j) out.push_back({left[0], left[j], left[j + 1]});
    return out;
}

}  // namespace m3055::model_file
