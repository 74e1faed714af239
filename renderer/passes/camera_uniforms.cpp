#include "passes/camera_uniforms.h"

namespace m3055 {

void set_camera_uniforms(const GlApi& gl, unsigned program, const CameraFrame& frame) {
    auto loc = [&](const char* name) { return gl.GetUniformLocation(program, name); };
    auto vec3 = [&](const char* name, const dvec3& v) { gl.Uniform3f(loc(name), float(v.x), float(v.y), float(v.z)); };
    gl.Uniform2f(loc("u_viewport"), float(frame.width), float(frame.height));
    gl.Uniform1i(loc("u_projection"), frame.projection == Projection::perspective ? 0 : 1);
    vec3("u_cam_position", frame.position);
    vec3("u_cam_forward", frame.forward);
    vec3("u_cam_right", frame.right);
    vec3("u_cam_up", frame.up);
    gl.Uniform2f(loc("u_cam_extent"), float(frame.extent_x), float(frame.extent_y));
    gl.Uniform2f(loc("u_depth_range"), float(frame.near), float(frame.far));
    gl.Uniform1i(loc("u_materials"), 0);
}

}  // namespace m3055
