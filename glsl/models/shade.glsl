// Every model, selected per object. The renderer may compile a program with
// only the models a scene uses (HAS_* defines); a general program has them all.
#include "common/features.glsl"
#include "common/math.glsl"
#include "common/material.glsl"
#include "common/lights.glsl"
#include "terms/beckmann.glsl"
#include "terms/ct_geometry.glsl"
#include "terms/kay_opacity.glsl"
#include "terms/highlight_blend.glsl"
#include "models/highlight.glsl"
#include "models/translucent.glsl"
#include "models/metal.glsl"
#ifdef HAS_CLASSIC_FAMILY
#include "models/classic.glsl"
#endif

// An opaque point (every model but translucent).
vec3 shade_opaque(Material mat, vec3 P, vec3 N, vec3 V) {
#ifdef HAS_CLASSIC_FAMILY
    if (mat.model >= MODEL_LAMBERT) return shade_classic(mat, P, N, V);
#endif
#if defined(HAS_HIGHLIGHT) && defined(HAS_METAL_FAMILY)
    if (mat.model == MODEL_HIGHLIGHT) return shade_highlight(mat, P, N, V);
    return shade_metal(mat, P, N, V);
#elif defined(HAS_HIGHLIGHT)
    return shade_highlight(mat, P, N, V);
#elif defined(HAS_METAL_FAMILY)
    return shade_metal(mat, P, N, V);
#else
    return vec3(0.0);  // a pass with no opaque model draws nothing
#endif
}
