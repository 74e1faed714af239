#version 330 core
// Benchmark only (m3055 bench): a sphere as a tessellated UV mesh instead of the
// exact ray-cast impostor, to measure what tessellation costs in accuracy.
// Shading is the same models/shade.glsl; only geometry and interpolation differ:
//   default: per pixel (Phong interpolation) - position and normal interpolated,
//            the fragment shader shades;
//   GOURAUD: per vertex - this shader shades, the colour is interpolated.
#include "common/camera.glsl"
#include "common/projection.glsl"
#ifdef GOURAUD
#include "models/shade.glsl"
uniform int u_material;
out vec3 v_color;
#else
out vec3 v_position;
out vec3 v_normal;
#endif

layout(location = 0) in vec3 a_unit;  // point on the unit sphere = its normal

uniform vec4 u_sphere;  // centre xyz, radius


void main() {
    vec3 P = u_sphere.xyz + u_sphere.w * a_unit;
    gl_Position = clip_position(P);
#ifdef GOURAUD
    vec3 V = u_projection == 0 ? normalize(u_cam_position - P) : -u_cam_forward;
    v_color = shade_opaque(fetch_material(u_material), P, a_unit, V);
#else
    v_position = P;
    v_normal = a_unit;
#endif
}
