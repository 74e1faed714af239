#version 330 core
// Benchmark only: the fragment half of passes/mesh_sphere.vert.
#ifdef GOURAUD
in vec3 v_color;
#else
#include "common/camera.glsl"
#include "models/shade.glsl"
uniform int u_material;
in vec3 v_position;
in vec3 v_normal;
#endif

layout(location = 0) out vec4 o_color;

void main() {
#ifdef GOURAUD
    o_color = vec4(v_color, 1.0);
#else
    // The interpolated normal is shorter than 1 inside a facet: renormalize, as
    // per-pixel shading of a mesh does. P lies on the flat facet, not the sphere.
    vec3 N = normalize(v_normal);
    vec3 V = u_projection == 0 ? normalize(u_cam_position - v_position) : -u_cam_forward;
    o_color = vec4(shade_opaque(fetch_material(u_material), v_position, N, V), 1.0);
#endif
}
