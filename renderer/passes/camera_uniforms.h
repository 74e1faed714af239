// Sets the camera uniforms of glsl/common/camera.glsl (and u_materials, the
// material buffer on texture unit 0) on the program in use. Shared by every
// pass that shades with the scene's camera: spheres, meshes, the bench's meshes.
#pragma once

#include "gl/gl_api.h"
#include "passes/camera_frame.h"

namespace m3055 {

void set_camera_uniforms(const GlApi& gl, unsigned program, const CameraFrame& frame);

}  // namespace m3055
