#include "scene/shape_limits.h"

namespace m3055 {

int segments_of(const Object& object) {
    if (object.segments > 0) return object.segments;
    return object.shape == Shape::torus ? kDefaultTorusSegments : kDefaultSegments;
}

std::size_t triangle_count(const Object& object) {
    const std::size_t n = std::size_t(segments_of(object));
    switch (object.shape) {
        case Shape::sphere: return 0;
        case Shape::plane: return 2;
        case Shape::cube: return 12;
        case Shape::cylinder: return object.capped ? 4 * n : 2 * n;
        case Shape::torus: return 2 * n * n;
        case Shape::mesh: return object.model ? object.model->triangles() : 0;
    }
    return 0;
}

}  // namespace m3055
