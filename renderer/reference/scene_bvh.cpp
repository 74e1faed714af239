#include "reference/scene_bvh.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace m3055::ref {

namespace {

constexpr std::uint32_t kObjectsPerLeaf = 2;

// Either root of |O + t D - C|^2 = r^2 in (0, t_max): the solid sphere blocks
// the segment whether it starts outside or inside it. The distance of the
// centre from the line comes from q = oc - b D, without the cancellation of
// b^2 - (oc.oc - r^2) (as intersect_sphere).
bool sphere_blocks(const Ray& ray, const dvec3& center, double radius, double t_max) {
    const dvec3 oc = ray.origin - center;
    const double b = glm::dot(oc, ray.dir);
    const dvec3 q = oc - b * ray.dir;
    const double h2 = radius * radius - glm::dot(q, q);
    if (h2 < 0.0) return false;
    const double h = std::sqrt(h2);
    const double t_near = -b - h, t_far = -b + h;
    return (t_near > 0.0 && t_near < t_max) || (t_far > 0.0 && t_far < t_max);
}

}  // namespace

SceneBvh::SceneBvh(const Scene& scene) {
    const std::size_t count = scene.objects.size();
    centers_.resize(count);
    radii_.resize(count);
    lo_.resize(count);
    hi_.resize(count);
    meshes_.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const Object& object = scene.objects[i];
        centers_[i] = object.center;
        radii_[i] = object.radius;
        if (object.shape == Shape::sphere) {
            lo_[i] = object.center - dvec3(object.radius);
            hi_[i] = object.center + dvec3(object.radius);
            continue;
        }
        meshes_[i] = std::make_unique<MeshIntersector>(geometry::make_mesh(object));
        lo_[i] = meshes_[i]->lo();
        hi_[i] = meshes_[i]->hi();
    }
    order_.resize(count);
    for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
    if (!order_.empty()) build(0, std::uint32_t(order_.size()));
}

// Median split of the boxes' centres along the longest axis of their bounds.
std::uint32_t SceneBvh::build(std::uint32_t begin, std::uint32_t end) {
    const std::uint32_t index = std::uint32_t(nodes_.size());
    nodes_.push_back({});
    dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (std::uint32_t i = begin; i < end; ++i) lo = glm::min(lo, lo_[order_[i]]), hi = glm::max(hi, hi_[order_[i]]);
    nodes_[index].lo = lo, nodes_[index].hi = hi;
    if (end - begin <= kObjectsPerLeaf) {
        nodes_[index].first = begin, nodes_[index].count = end - begin;
        return index;
    }
    const dvec3 extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const std::uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) {
                         return lo_[a][axis] + hi_[a][axis] < lo_[b][axis] + hi_[b][axis];
                     });
    const std::uint32_t left = build(begin, middle);
    const std::uint32_t right = build(middle, end);
    nodes_[index].first = left, nodes_[index].count = 0, nodes_[index].right = right;
    return index;
}

bool SceneBvh::object_blocks(std::uint32_t object, const Ray& ray, double t_max) const {
    if (const MeshIntersector* mesh = meshes_[object].get()) return mesh->any_hit(ray, t_max);
    return sphere_blocks(ray, centers_[object], radii_[object], t_max);
}

bool SceneBvh::blocked(const Ray& ray, double t_max) const {
    if (nodes_.empty()) return false;
    const dvec3 inv_dir = 1.0 / ray.dir;
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (!ray_meets_box(ray, inv_dir, node.lo, node.hi, t_max)) continue;
        if (node.count == 0) {
            stack[top++] = node.first;
            stack[top++] = node.right;
            continue;
        }
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
            if (object_blocks(order_[i], ray, t_max)) return true;
    }
    return false;
}

bool SceneBvh::sees(const dvec3& P, const dvec3& N, const dvec3& direction, double distance) const {
    const double eps = 1e-9 * std::max({1.0, std::fabs(P.x), std::fabs(P.y), std::fabs(P.z)});
    return !blocked(Ray{P + eps * N, direction}, distance);
}

}  // namespace m3055::ref
