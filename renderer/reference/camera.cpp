// Geometry of the accuracy-checked path (docs/spec.md#3-geometry): pixel-centre camera rays
// and exact ray/sphere intersection.
#include "reference/reference.h"

#include "numeric/angles.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace m3055::ref {

namespace {
using numeric::kPi;
}  // namespace

// docs/spec.md#3-geometry: pixel (x, y), y = 0 the top row, sampled at its centre.
Ray camera_ray(const Camera& camera, int width, int height, int x, int y) {
    const double u = 2.0 * (double(x) + 0.5) / double(width) - 1.0;
    const double v = 1.0 - 2.0 * (double(y) + 0.5) / double(height);
    const double aspect = double(width) / double(height);

    const dvec3 f = glm::normalize(camera.target - camera.position);
    const dvec3 r = glm::normalize(glm::cross(f, camera.up));
    const dvec3 u_cam = glm::cross(r, f);

    Ray ray;
    if (camera.projection == Projection::perspective) {
        const double tan_half = std::tan(camera.fov_y_deg * kPi / 360.0);  // tan(fov / 2)
        ray.origin = camera.position;
        ray.dir = glm::normalize(f + (u * tan_half * aspect) * r + (v * tan_half) * u_cam);
    } else {
        const double half = camera.height / 2.0;
        ray.origin = camera.position + (u * half * aspect) * r + (v * half) * u_cam;
        ray.dir = f;
    }
    return ray;
}

// The numerically stable form: with oc = O - C and b = oc.D, the squared
// distance from the centre to the ray's line is q.q, q = oc - b D, which keeps
// its precision where b^2 - (oc.oc - r^2) would cancel. The near root
// t = -b - sqrt(r^2 - q.q) is the front face; it is <= 0 when the origin is
// inside the sphere (or the sphere is behind), and then there is no hit.
bool intersect_sphere(const Ray& ray, const dvec3& center, double radius, double* t) {
    const dvec3 oc = ray.origin - center;
    const double b = glm::dot(oc, ray.dir);
    const dvec3 q = oc - b * ray.dir;
    const double h2 = radius * radius - glm::dot(q, q);
    if (h2 < 0.0) return false;
    const double t_near = -b - std::sqrt(h2);
    if (!(t_near > 0.0)) return false;
    *t = t_near;
    return true;
}

}  // namespace m3055::ref
