#version 330 core
// BRDF grid pass (renderer/passes/brdf_grid.h): pixel (x, y) evaluates the
// material at N = +z with L = u_dirs_l[x], V = u_dirs_v[y] (or V = u_dirs_v[x]
// for pairs; unit, given on the CPU), through the same model code as passes/sphere.frag. Light 0 is a white
// point light of intensity 1 at the origin and P = -L, so light_sample gives
// exactly L with scale 1 (the stress test's trick); the result is the
// model's f = I / (pi N.L) on the classic models' scale (docs/models.md), or
// 0 where N.L <= 0.
#include "common/constants.glsl"
#include "models/shade.glsl"

uniform sampler2D u_dirs_l;
uniform sampler2D u_dirs_v;
uniform int u_paired;  // 1: one row, pixel x pairs L[x] with V[x]

layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_transmittance;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 L = texelFetch(u_dirs_l, ivec2(pixel.x, 0), 0).xyz;
    vec3 V = texelFetch(u_dirs_v, ivec2(u_paired != 0 ? pixel.x : pixel.y, 0), 0).xyz;
    vec3 N = vec3(0.0, 0.0, 1.0);
    Material mat = fetch_material(0);
    vec3 I = shade_opaque(mat, -L, N, V);
    o_color = vec4(L.z > 0.0 ? I / (PI * L.z) : vec3(0.0), 1.0);
    o_transmittance = vec4(0.0);
}
