// The scene format's limits on meshed shapes (docs/shapes.md): segments a full
// circle, and the triangles a scene may hold. The loader enforces them; the
// meshes of geometry/ are built to them (make_mesh gives exactly
// triangle_count(object) triangles, tests/shape_mesh_test.cpp).
#pragma once

#include "scene/scene.h"

#include <cstddef>

namespace m3055 {

// Segments a full circle when an object gives none, chosen so that the
// shading error against the analytic surface stays below 5e-3 (a sixth of a
// 5-bit level) away from silhouettes for the spec example's highlight m = 10
// (tests/shape_mesh_test.cpp measures it; docs/shapes.md has the table):
// cylinders 64 (5.6 degree steps, measured 5e-4), tori 128 in both directions
// (curved both ways, measured 2.9e-3; 64 gives 1.1e-2).
inline constexpr int kDefaultSegments = 64;
inline constexpr int kDefaultTorusSegments = 128;
inline constexpr int kMinSegments = 3;
inline constexpr int kMaxSegments = 512;
// Every mesh of a scene together: the loader rejects scenes above this.
inline constexpr std::size_t kMaxSceneTriangles = 4000000;

// An object's segments: its own, or the default for its shape.
int segments_of(const Object& object);
// Triangles the object's mesh has (0 for a sphere), without building it.
std::size_t triangle_count(const Object& object);

}  // namespace m3055
