#include "reference/mesh_hits.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace m3055::ref {

namespace {

constexpr std::uint32_t kLeafSize = 4;

}  // namespace

bool ray_meets_box(const Ray& ray, const dvec3& inv_dir, const dvec3& lo, const dvec3& hi, double t_max) {
    double t0 = 0.0, t1 = t_max;
    for (int axis = 0; axis < 3; ++axis) {
        double a = (lo[axis] - ray.origin[axis]) * inv_dir[axis];
        double b = (hi[axis] - ray.origin[axis]) * inv_dir[axis];
        if (std::isnan(a) || std::isnan(b)) continue;  // 0 * inf: origin on the slab, parallel ray
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    return t0 <= t1;
}

MeshIntersector::MeshIntersector(geometry::Mesh mesh) : mesh_(std::move(mesh)) {
    order_.resize(mesh_.triangles());
    for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
    nodes_.reserve(2 * order_.size() / kLeafSize + 2);
    if (!order_.empty()) build(0, std::uint32_t(order_.size()));
}

// Median split of the triangles' centroids along the box's longest axis.
std::uint32_t MeshIntersector::build(std::uint32_t begin, std::uint32_t end) {
    const std::uint32_t index = std::uint32_t(nodes_.size());
    nodes_.push_back({});
    dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (std::uint32_t i = begin; i < end; ++i)
        for (int k = 0; k < 3; ++k) {
            const dvec3& p = mesh_.positions[mesh_.indices[3 * order_[i] + k]];
            lo = glm::min(lo, p), hi = glm::max(hi, p);
        }
    nodes_[index].lo = lo, nodes_[index].hi = hi;
    if (end - begin <= kLeafSize) {
        nodes_[index].first = begin, nodes_[index].count = end - begin;
        return index;
    }
    const dvec3 extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    auto centroid = [&](std::uint32_t t) {
        return mesh_.positions[mesh_.indices[3 * t]][axis] + mesh_.positions[mesh_.indices[3 * t + 1]][axis] +
               mesh_.positions[mesh_.indices[3 * t + 2]][axis];
    };
    const std::uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) { return centroid(a) < centroid(b); });
    const std::uint32_t left = build(begin, middle);
    const std::uint32_t right = build(middle, end);
    nodes_[index].first = left, nodes_[index].count = 0, nodes_[index].right = right;
    return index;
}

// Moeller-Trumbore. With e1 = b - a, e2 = c - a and the outward normal e1 x e2,
// det = e1 . (dir x e2) = -dir . (e1 x e2): the triangle faces the ray when det > 0.
bool MeshIntersector::hit_triangle(const Ray& ray, std::uint32_t triangle, MeshHit* hit) const {
    const std::uint32_t ia = mesh_.indices[3 * triangle], ib = mesh_.indices[3 * triangle + 1],
                        ic = mesh_.indices[3 * triangle + 2];
    const dvec3& a = mesh_.positions[ia];
    const dvec3 e1 = mesh_.positions[ib] - a, e2 = mesh_.positions[ic] - a;
    const dvec3 p = glm::cross(ray.dir, e2);
    const double det = glm::dot(e1, p);
    if (!(det > 0.0)) return false;  // back face or edge-on
    const dvec3 s = ray.origin - a;
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) return false;
    const dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(ray.dir, q) / det;
    if (v < 0.0 || u + v > 1.0) return false;
    const double t = glm::dot(e2, q) / det;
    if (!(t > 0.0)) return false;
    hit->t = t;
    hit->part = mesh_.parts[triangle];
    hit->group = mesh_.groups.empty() ? 0 : mesh_.groups[triangle];
    hit->N = glm::normalize((1.0 - u - v) * mesh_.normals[ia] + u * mesh_.normals[ib] + v * mesh_.normals[ic]);
    return true;
}

// Moeller-Trumbore from either side: det of either sign, t in (0, t_max).
bool MeshIntersector::blocks(const Ray& ray, std::uint32_t triangle, double t_max) const {
    const dvec3& a = mesh_.positions[mesh_.indices[3 * triangle]];
    const dvec3 e1 = mesh_.positions[mesh_.indices[3 * triangle + 1]] - a;
    const dvec3 e2 = mesh_.positions[mesh_.indices[3 * triangle + 2]] - a;
    const dvec3 p = glm::cross(ray.dir, e2);
    const double det = glm::dot(e1, p);
    if (det == 0.0) return false;  // edge-on: the neighbours it shares edges with are met instead
    const dvec3 s = ray.origin - a;
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) return false;
    const dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(ray.dir, q) / det;
    if (v < 0.0 || u + v > 1.0) return false;
    const double t = glm::dot(e2, q) / det;
    return t > 0.0 && t < t_max;
}

bool MeshIntersector::any_hit(const Ray& ray, double t_max) const {
    if (nodes_.empty()) return false;
    const dvec3 inv_dir = 1.0 / ray.dir;
    std::uint32_t stack[64];  // a median split of 4 million triangles is 21 levels deep
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (!ray_meets_box(ray, inv_dir, node.lo, node.hi, std::numeric_limits<double>::infinity())) continue;
        if (node.count == 0) {
            stack[top++] = node.first;
            stack[top++] = node.right;
            continue;
        }
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
            if (blocks(ray, order_[i], t_max)) return true;
    }
    return false;
}

dvec3 MeshIntersector::lo() const {
    return nodes_.empty() ? dvec3(std::numeric_limits<double>::infinity()) : nodes_[0].lo;
}

dvec3 MeshIntersector::hi() const {
    return nodes_.empty() ? dvec3(-std::numeric_limits<double>::infinity()) : nodes_[0].hi;
}

std::vector<MeshHit> MeshIntersector::intersect_all(const Ray& ray) const {
    std::vector<MeshHit> hits;
    if (nodes_.empty()) return hits;
    const dvec3 inv_dir = 1.0 / ray.dir;
    std::vector<std::uint32_t> stack = {0};
    while (!stack.empty()) {
        const Node& node = nodes_[stack.back()];
        stack.pop_back();
        if (!ray_meets_box(ray, inv_dir, node.lo, node.hi, std::numeric_limits<double>::infinity())) continue;
        if (node.count == 0) {
            stack.push_back(node.first);
            stack.push_back(node.right);
            continue;
        }
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
            MeshHit hit;
            if (hit_triangle(ray, order_[i], &hit)) hits.push_back(hit);
        }
    }
    std::sort(hits.begin(), hits.end(), [](const MeshHit& a, const MeshHit& b) {
        return a.t != b.t ? a.t < b.t : a.part < b.part;
    });
    // One hit where a ray passes through a shared edge or vertex.
    std::vector<MeshHit> unique;
    for (const MeshHit& hit : hits)
        if (unique.empty() || hit.t - unique.back().t > 1e-9 * std::max(1.0, hit.t)) unique.push_back(hit);
    return unique;
}

}  // namespace m3055::ref
