#version 330 core
// Stress-test pass (tests/stress_test.cpp): one input per pixel, read from
// float textures, shaded by the same model code as passes/sphere.frag.
// The inputs are raw (any length); they are normalized here exactly as the
// sphere pass normalizes its N and V. Light 0 of the stress test is a point
// light at the origin, so the per-pixel position P = -L_raw gives every pixel
// its own light direction through light_sample.
#include "models/shade.glsl"

uniform sampler2D u_normal;    // raw N
uniform sampler2D u_view;      // raw V (towards the viewer)
uniform sampler2D u_position;  // P
uniform int u_width;           // pixels per row: material record = y * width + x

layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_transmittance;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 N = normalize(texelFetch(u_normal, pixel, 0).xyz);
    vec3 V = normalize(texelFetch(u_view, pixel, 0).xyz);
    vec3 P = texelFetch(u_position, pixel, 0).xyz;
    Material mat = fetch_material(pixel.y * u_width + pixel.x);
    if (mat.family == FAMILY_TRANSLUCENT) {
        vec3 color, transmittance;
        translucent_shade(mat, P, N, V, color, transmittance);
        o_color = vec4(color, 1.0);
        o_transmittance = vec4(transmittance, 1.0);
    } else {
        o_color = vec4(shade_opaque(mat, P, N, V), 1.0);
        o_transmittance = vec4(0.0, 0.0, 0.0, 1.0);
    }
}
