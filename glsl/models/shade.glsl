// Every model, selected per object by its family and then its model id. The
// models' files, ids, struct Material and the families' dispatchers to the
// models' hooks are generated from the model table (generated/*.glsl, by
// renderer/models/glsl_generator.cpp); a program has only the models of its
// HAS_* defines (all of them in a general program).
#include "common/features.glsl"
#include "common/math.glsl"
#include "generated/material.glsl"
#include "common/lights.glsl"
#include "generated/models.glsl"
#ifdef HAS_FAMILY_BRDF
#include "brdf/shade_brdf.glsl"
#endif

// An opaque point (every family but translucent). C++ twin: ref::shade_opaque.
vec3 shade_opaque(Material mat, vec3 P, vec3 N, vec3 V) {
#ifdef HAS_FAMILY_CLASSIC
    if (mat.family == FAMILY_CLASSIC) return shade_classic(mat, P, N, V);
#endif
#ifdef HAS_FAMILY_METAL
    if (mat.family == FAMILY_METAL) return shade_metal(mat, P, N, V);
#endif
#ifdef HAS_FAMILY_BRDF
    if (mat.family == FAMILY_BRDF) return shade_brdf(mat, P, N, V);
#endif
#ifdef HAS_FAMILY_OPAQUE
    if (mat.family == FAMILY_OPAQUE) return opaque_shade(mat, P, N, V);
#endif
    return vec3(0.0);  // a pass with no opaque model draws nothing
}
