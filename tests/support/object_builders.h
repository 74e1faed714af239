// Objects of each shape in one line, for tests that build scenes by hand
// (docs/spec.md#7-scene-files, docs/shapes.md: the fields each shape uses).
#pragma once

#include "scene/scene.h"

namespace m3055::test {

Object sphere(dvec3 center, double radius, Material material);
Object cube(dvec3 center, double size, dvec3 rotation_deg, Material material);
// `axis` need not be unit: it is normalized, as the loader does.
Object cylinder(dvec3 center, dvec3 axis, double radius, double height, bool capped, Material material);
Object torus(dvec3 center, dvec3 axis, double major, double minor, Material material);

}  // namespace m3055::test
