#version 330 core
// Per-pixel shading of a mesh (renderer/geometry/). Perspective-correct
// interpolation gives the position and barycentric normal at the point where
// the pixel-centre ray meets the triangle: exactly what the CPU reference
// ray-casts (reference/mesh_hits.cpp). Back faces are culled (docs/spec.md#3-geometry).
// TRANSLUCENT_PASS: as passes/sphere.frag, a premultiplied colour and a
// per-channel transmittance for dual-source blending; TWO_PASS_BLEND as there.
#include "common/camera.glsl"
#include "models/shade.glsl"

in vec3 v_position;
in vec3 v_normal;
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
    // The interpolated normal is shorter than 1 inside a triangle: renormalize.
    vec3 N = normalize(v_normal);
    // V = -ray direction, the same ray as the spheres' (perspective: towards the
    // eye, normalize(eye - P); orthographic: -f).
    vec3 V = -camera_ray(gl_FragCoord.xy).dir;
    vec3 P = v_position;

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
