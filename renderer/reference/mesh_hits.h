// Ray casting of the shapes' triangle meshes (geometry/mesh.h) in double, for
// the CPU reference: Moeller-Trumbore per triangle, front faces only, the
// normal interpolated with the hit's barycentric coordinates and normalized.
// Rasterizing the same mesh with perspective-correct interpolation gives the
// same values at the pixel-centre ray's hit point, so the GPU's mesh pass is
// compared with the reference like the exact spheres. A bounding-volume
// hierarchy keeps a frame of a 8192-triangle torus to a fraction of a second.
#pragma once

#include "geometry/mesh.h"
#include "reference/reference.h"

#include <vector>

namespace m3055::ref {

// Slab test: whether the ray meets the box [lo, hi] for t in (0, t_max);
// inv_dir = 1 / ray.dir (a 0 * inf from a parallel ray on a slab counts as inside).
bool ray_meets_box(const Ray& ray, const dvec3& inv_dir, const dvec3& lo, const dvec3& hi, double t_max);

struct MeshHit {
    double t;  // ray parameter, > 0
    std::uint32_t part;   // the triangle's smooth piece (geometry::Mesh::parts)
    std::uint32_t group;  // its group (geometry::Mesh::groups; 0 when the mesh has none)
    dvec3 N;   // unit, barycentric interpolation of the vertex normals
};

class MeshIntersector {
public:
    explicit MeshIntersector(geometry::Mesh mesh);
    const geometry::Mesh& mesh() const { return mesh_; }

    // Every front-face hit with t > 0, nearest first; a ray through an edge or
    // vertex shared by several triangles gives one hit there, not several.
    std::vector<MeshHit> intersect_all(const Ray& ray) const;

    // Whether the ray meets a triangle from either side at t in (0, t_max)
    // (t_max may be infinity): what blocks a shadow ray (reference/scene_bvh.h).
    bool any_hit(const Ray& ray, double t_max) const;

    // The box around every triangle (a point at infinity's box when there are none).
    dvec3 lo() const;
    dvec3 hi() const;

private:
    struct Node {
        dvec3 lo, hi;           // bounding box
        std::uint32_t first;    // leaf: first entry of order_; inner: left child
        std::uint32_t count;    // leaf: triangle count; inner: 0
        std::uint32_t right;    // inner: right child
    };
    std::uint32_t build(std::uint32_t begin, std::uint32_t end);
    bool hit_triangle(const Ray& ray, std::uint32_t triangle, MeshHit* hit) const;
    bool blocks(const Ray& ray, std::uint32_t triangle, double t_max) const;

    geometry::Mesh mesh_;
    std::vector<std::uint32_t> order_;  // triangle indices, grouped by leaf
    std::vector<Node> nodes_;
};

}  // namespace m3055::ref
