// the docs/spec.md#3-geometry camera as a projection, for rasterized meshes: the same rays as
// camera_ray() (common/camera.glsl, included first) and the same depth as
// window_depth(), so meshes and ray-cast spheres share one depth buffer.
//   perspective:  x_ndc = x_cam / (z_cam * extent_x), y_ndc = y_cam / (z_cam * extent_y), w = z_cam
//   orthographic: x_ndc = x_cam / extent_x,           y_ndc = y_cam / extent_y,           w = 1
// (x_cam, y_cam, z_cam) = ((P - eye).r, (P - eye).u_cam, (P - eye).f).
// Perspective divides by w = z_cam, so clip x, y are x_cam / extent_x, y_cam / extent_y.
vec4 clip_position(vec3 P) {
    vec3 d = P - u_cam_position;
    float z = dot(d, u_cam_forward);
    vec2 xy = vec2(dot(d, u_cam_right), dot(d, u_cam_up)) / u_cam_extent;
    float n = u_depth_range.x, f = u_depth_range.y;
    if (u_projection == 0) return vec4(xy, (f + n) / (f - n) * z - 2.0 * f * n / (f - n), z);
    return vec4(xy, 2.0 * (z - n) / (f - n) - 1.0, 1.0);
}
