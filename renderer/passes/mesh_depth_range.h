// The depth range (distances along f) of the part of a mesh inside the view
// frustum. make_camera_frame fits near and far to the objects; a mesh whose
// bounding sphere reaches behind the camera (a floor under it) would otherwise
// force near to ~0 and waste the depth buffer's precision where a sphere
// rests on the floor.
#pragma once

#include "geometry/mesh.h"

#include <optional>
#include <utility>

namespace m3055 {

struct CameraFrame;

// {z_min, z_max} over the mesh clipped to the perspective frustum (z > 0);
// std::nullopt when no part of it is in view.
std::optional<std::pair<double, double>> visible_depth_range(const CameraFrame& frame, const geometry::Mesh& mesh);

}  // namespace m3055
