// The camera as the shaders use it (docs/spec.md#3-geometry), computed once per frame in double.
#pragma once

#include "scene/scene.h"

namespace m3055 {

struct CameraFrame {
    Projection projection = Projection::perspective;
    dvec3 position, forward, right, up;  // f, r = normalize(f x up), u_cam = r x f
    double extent_x = 1, extent_y = 1;   // see glsl/common/camera.glsl: u_cam_extent
    double near = 0.1, far = 100;        // distances along f that bound every object
    int width = 1, height = 1;
};

// Near and far are fitted to the objects so the depth buffer's precision is spent on them.
CameraFrame make_camera_frame(const Camera& camera, const Display& display,
                              const std::vector<Object>& objects);

}  // namespace m3055
