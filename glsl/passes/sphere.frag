#version 330 core
// Exact spheres: ray-cast per pixel, shaded, with the true depth.
// TRANSLUCENT_PASS: outputs a premultiplied colour and a per-channel
// transmittance for dual-source blending, dst = color + transmittance * dst,
// which is exactly the docs/spec.md#42-translucent C = S + (1-S) t C1 + (1-S)(1-t) C_B.
// TWO_PASS_BLEND (with TRANSLUCENT_PASS): one output, the transmittance or the
// colour by u_blend_step, for the blend without dual sources
// (renderer/passes/translucent_blend.h).
#include "common/camera.glsl"
#include "common/sphere.glsl"
#include "models/shade.glsl"

flat in vec4 v_sphere;
flat in int v_material;

#if defined(TRANSLUCENT_PASS) && !defined(TWO_PASS_BLEND)
layout(location = 0, index = 0) out vec4 o_color;
layout(location = 0, index = 1) out vec4 o_transmittance;
#else
layout(location = 0) out vec4 o_color;
#endif
#ifdef TWO_PASS_BLEND
uniform int u_blend_step;  // passes/translucent_blend.h: 0 the multiply by t, 1 the add of the colour
#endif

void main() {
    Ray ray = camera_ray(gl_FragCoord.xy);
    vec3 oc = ray.origin - v_sphere.xyz;
    float t;
    if (!intersect_sphere(oc, ray.dir, v_sphere.w, t)) discard;
    vec3 P = ray.origin + t * ray.dir;
    vec3 N = normalize(oc + t * ray.dir);
    vec3 V = -ray.dir;
    gl_FragDepth = window_depth(P);

    Material mat = fetch_material(v_material);
#ifdef TRANSLUCENT_PASS
    vec3 color, transmittance;
    translucent_shade(mat, P, N, V, color, transmittance);
#ifdef TWO_PASS_BLEND
    o_color = vec4(u_blend_step == 0 ? transmittance : color, 1.0);
#else
    o_color = vec4(color, 1.0);
    o_transmittance = vec4(transmittance, 1.0);
#endif
#else
    o_color = vec4(shade_opaque(mat, P, N, V), 1.0);
#endif
}
