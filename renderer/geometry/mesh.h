// Triangle meshes of the non-sphere shapes (docs/shapes.md), generated in
// double, in world space. The GPU mesh pass (passes/mesh_pass.cpp) and the CPU
// reference (reference/mesh_hits.cpp) use the SAME mesh, so they are compared
// pixel by pixel like the exact spheres; tests/shape_mesh_test.cpp holds the
// mesh against the analytic shape.
//
// Conventions:
// - triangles are counter-clockwise seen from outside: (b - a) x (c - a)
//   points out of the solid (for the plane: along its normal), so GL's default
//   front face and the docs/spec.md#3-geometry "only front faces are shaded" agree;
// - normals are unit, per vertex: the analytic normal where the surface is
//   smooth (cylinder side, torus), one flat normal per cube face and per
//   cylinder cap (those vertices are not shared across the crease);
// - `parts` numbers the smooth pieces of a shape (cube faces 0-5, cylinder
//   side 0 / bottom 1 / top 2, plane and torus 0): the reference's coverage
//   signature includes them, so creases are excluded from pixel comparisons
//   like silhouettes; a model file's are its smooth pieces (model_file/model.h);
// - `groups` (a model file's only) gives each triangle's group, whose
//   material is material_of(object, group) (empty: group 0 throughout).
#pragma once

#include "scene/scene.h"
#include "scene/shape_limits.h"

#include <cstdint>
#include <vector>

namespace m3055::geometry {

struct Mesh {
    std::vector<dvec3> positions;
    std::vector<dvec3> normals;          // unit, one per position
    std::vector<std::uint32_t> indices;  // 3 per triangle
    std::vector<std::uint32_t> parts;    // one per triangle
    std::vector<std::uint32_t> groups;   // one per triangle, or empty
    std::size_t triangles() const { return indices.size() / 3; }
};

// The segment defaults and limits, segments_of and triangle_count are the
// scene format's (scene/shape_limits.h): the loader checks them; make_mesh
// gives exactly triangle_count(object) triangles.


// The orthonormal frame around a unit axis A (unit: the loader normalizes it) used by every shape: T is the
// world axis least aligned with A (ties: x, then y, then z) made perpendicular
// to A, and B = A x T, so (T, B, A) is right-handed.
struct AxisFrame {
    dvec3 t, b, a;
};
AxisFrame axis_frame(const dvec3& axis);

// Rotation of the cube: about world x by rx, then y by ry, then z by rz (degrees).
dvec3 rotate_xyz(const dvec3& v, const dvec3& rotation_deg);

Mesh make_plane(const dvec3& center, const dvec3& normal, double size);
Mesh make_cube(const dvec3& center, double size, const dvec3& rotation_deg);
Mesh make_cylinder(const dvec3& center, const dvec3& axis, double radius, double height, bool capped,
                   int segments);
Mesh make_torus(const dvec3& center, const dvec3& axis, double major_radius, double minor_radius,
                int segments);
// A model file's triangles placed: its bounding box centred on `center`,
// scaled uniformly so that its largest side is `size`, then rotated about
// `center` as cubes are (rotate_xyz).
Mesh place_model(const model_file::Model& model, const dvec3& center, double size, const dvec3& rotation_deg);

// The mesh of any non-sphere object (empty for a sphere).
Mesh make_mesh(const Object& object);

// Radius of a sphere around object.center containing the whole object.
double bounding_radius(const Object& object);

}  // namespace m3055::geometry
