#include "passes/camera_frame.h"

#include "geometry/mesh.h"
#include "passes/mesh_depth_range.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace m3055 {

CameraFrame make_camera_frame(const Camera& camera, const Display& display,
                              const std::vector<Object>& objects) {
    CameraFrame frame;
    frame.projection = camera.projection;
    frame.width = display.width;
    frame.height = display.height;
    frame.position = camera.position;
    frame.forward = glm::normalize(camera.target - camera.position);
    frame.right = glm::normalize(glm::cross(frame.forward, camera.up));
    frame.up = glm::cross(frame.right, frame.forward);
    const double aspect = double(display.width) / double(display.height);
    const double half = camera.projection == Projection::perspective
                            ? std::tan(camera.fov_y_deg * M_PI / 360.0)
                            : camera.height / 2.0;
    frame.extent_x = half * aspect;
    frame.extent_y = half;

    double z_min = 1e300, z_max = -1e300;
    for (const auto& object : objects) {
        const double z = glm::dot(object.center - camera.position, frame.forward);
        const double reach = geometry::bounding_radius(object);
        // A mesh reaching behind a perspective camera (a floor under it): only
        // its part in view counts (passes/mesh_depth_range.h).
        if (object.shape != Shape::sphere && camera.projection == Projection::perspective && z - reach <= 0) {
            if (auto range = visible_depth_range(frame, geometry::make_mesh(object))) {
                z_min = std::min(z_min, range->first);
                z_max = std::max(z_max, range->second);
            }
            continue;
        }
        z_min = std::min(z_min, z - reach);
        z_max = std::max(z_max, z + reach);
    }
    if (z_min > z_max) z_min = 0.1, z_max = 100;  // nothing (in view)
    frame.far = std::max(z_max, 1e-3) * 1.001 + 1e-6;
    // Perspective depth needs near > 0; objects reaching behind it are clipped
    // to depth 0 there, which only matters for spheres around the camera.
    frame.near = camera.projection == Projection::perspective
                     ? std::max(z_min * 0.999, frame.far * 1e-6)
                     : std::min(z_min, 0.0) - 1e-6;
    return frame;
}

}  // namespace m3055
