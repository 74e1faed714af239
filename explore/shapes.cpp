#include "explore/shapes.h"

#include "geometry/mesh.h"

#include <algorithm>

namespace m3055::explore {

std::optional<Shape> parse_shape(const std::string& name) {
    for (Shape shape : kAllShapes)
        if (name == to_string(shape)) return shape;
    return std::nullopt;
}

void set_shape(Object& object, Shape shape) {
    if (object.shape == shape) return;
    const double r = geometry::bounding_radius(object);  // the old shape's extent
    const double size = std::max(r, 0.01);
    object.shape = shape;
    object.axis = {0.0, 1.0, 0.0};
    switch (shape) {
        case Shape::sphere: object.radius = size; break;
        case Shape::plane:
            object.center.y -= size;  // a floor under where the object was
            object.size = 6.0 * size;
            break;
        case Shape::cube: object.size = 1.6 * size; break;
        case Shape::cylinder:
            object.radius = 0.6 * size;
            object.height = 1.6 * size;
            break;
        case Shape::torus:
            object.major_radius = 0.72 * size;
            object.minor_radius = 0.28 * size;
            break;
        case Shape::mesh: object.size = 2.0 * size; break;  // only with a model file (kAllShapes has none)
    }
    if (shape != Shape::mesh) {
        // A model file's triangles and group materials go with its shape; the first group's material stays.
        object.file.clear();
        object.model.reset();
        object.groups.clear();
    }
}

}  // namespace m3055::explore
