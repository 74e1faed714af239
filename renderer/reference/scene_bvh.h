// Exact visibility in double against every object of a scene, for the shadows
// of the CPU reference (docs/spec.md#75-area-lights-the-sky-and-shadows): a
// bounding-volume hierarchy over the objects' bounding boxes, with each mesh's
// own hierarchy below it (reference/mesh_hits.h), so that an any-hit query
// costs about the logarithm of the objects and triangles it could meet.
// Spheres are exact; meshes (planes, cubes, cylinders, tori) block from both
// sides of every triangle; translucent objects block as opaque ones do.
#pragma once

#include "reference/mesh_hits.h"
#include "reference/reference.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace m3055::ref {

class SceneBvh {
public:
    explicit SceneBvh(const Scene& scene);

    // The mesh of object `index` (made once, here), or nullptr for a sphere.
    const MeshIntersector* mesh(std::size_t index) const { return meshes_[index].get(); }

    // Whether anything lies on the ray for t in (0, t_max) (t_max may be infinity).
    bool blocked(const Ray& ray, double t_max) const;

    // Whether surface point P, of unit normal N, sees along unit `direction`
    // up to `distance` (infinity: to the end of the scene) with nothing in the
    // way. The ray starts at P + eps N, eps = 1e-9 max(1, |P|_inf): P itself is
    // on a surface to within rounding (~1e-16 |P| in double), and the offset
    // keeps that surface from hiding the point from itself. Geometry within eps
    // of P does not block; nothing in a scene is that thin (coordinates within
    // 1e6, sizes from 1e-6).
    bool sees(const dvec3& P, const dvec3& N, const dvec3& direction, double distance) const;

private:
    struct Node {
        dvec3 lo, hi;         // bounding box
        std::uint32_t first;  // leaf: first entry of order_; inner: left child
        std::uint32_t count;  // leaf: object count; inner: 0
        std::uint32_t right;  // inner: right child
    };
    std::uint32_t build(std::uint32_t begin, std::uint32_t end);
    bool object_blocks(std::uint32_t object, const Ray& ray, double t_max) const;

    std::vector<dvec3> centers_;
    std::vector<double> radii_;  // spheres
    std::vector<dvec3> lo_, hi_;  // each object's box
    std::vector<std::unique_ptr<MeshIntersector>> meshes_;
    std::vector<std::uint32_t> order_;
    std::vector<Node> nodes_;
};

}  // namespace m3055::ref
