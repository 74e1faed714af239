#include "object_builders.h"

#include <glm/geometric.hpp>

namespace m3055::test {

Object sphere(dvec3 center, double radius, Material material) {
    Object o;
    o.center = center, o.radius = radius, o.material = std::move(material);
    return o;
}

Object cube(dvec3 center, double size, dvec3 rotation_deg, Material material) {
    Object o;
    o.shape = Shape::cube;
    o.center = center, o.size = size, o.rotation_deg = rotation_deg;
    o.material = std::move(material);
    return o;
}

Object cylinder(dvec3 center, dvec3 axis, double radius, double height, bool capped, Material material) {
    Object o;
    o.shape = Shape::cylinder;
    o.center = center, o.axis = glm::normalize(axis), o.radius = radius, o.height = height, o.capped = capped;
    o.material = std::move(material);
    return o;
}

Object torus(dvec3 center, dvec3 axis, double major, double minor, Material material) {
    Object o;
    o.shape = Shape::torus;
    o.center = center, o.axis = glm::normalize(axis), o.major_radius = major, o.minor_radius = minor;
    o.material = std::move(material);
    return o;
}

}  // namespace m3055::test
