// docs/spec.md#3-geometry: the ray through a pixel centre. C++ twin: ref::camera_ray.

uniform vec2 u_viewport;        // display width, height in pixels
uniform int u_projection;       // 0 perspective, 1 orthographic
uniform vec3 u_cam_position;
uniform vec3 u_cam_forward;     // f
uniform vec3 u_cam_right;       // r = normalize(f x up)
uniform vec3 u_cam_up;          // u_cam = r x f
// perspective: (tan(fov/2) * aspect, tan(fov/2)); orthographic: (height/2 * aspect, height/2)
uniform vec2 u_cam_extent;
uniform vec2 u_depth_range;     // near, far: distances along f that bound the scene

struct Ray {
    vec3 origin;
    vec3 dir;  // unit
};

// gl_FragCoord.xy is the pixel centre (x + 0.5, y_gl + 0.5) with y_gl counted
// from the bottom, so u = 2(x + 0.5)/w - 1 and v = 1 - 2(y + 0.5)/h (y from the
// top) are both 2 * gl_FragCoord / size - 1.
Ray camera_ray(vec2 frag_coord) {
    vec2 uv = 2.0 * frag_coord / u_viewport - 1.0;
    Ray ray;
    if (u_projection == 0) {
        ray.origin = u_cam_position;
        ray.dir = normalize(u_cam_forward + uv.x * u_cam_extent.x * u_cam_right +
                            uv.y * u_cam_extent.y * u_cam_up);
    } else {
        ray.origin = u_cam_position + uv.x * u_cam_extent.x * u_cam_right +
                     uv.y * u_cam_extent.y * u_cam_up;
        ray.dir = u_cam_forward;
    }
    return ray;
}

// Window depth of a point, as a standard projection matrix with the same near
// and far planes would give it, so rasterized geometry and ray-cast spheres
// share one depth buffer.
float window_depth(vec3 P) {
    float z = dot(P - u_cam_position, u_cam_forward);
    float n = u_depth_range.x, f = u_depth_range.y;
    float ndc = u_projection == 0 ? (f + n) / (f - n) - 2.0 * f * n / ((f - n) * z)
                                  : 2.0 * (z - n) / (f - n) - 1.0;
    return clamp(0.5 * ndc + 0.5, 0.0, 1.0);
}
