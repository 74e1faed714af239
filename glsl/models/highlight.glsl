// docs/spec.md#41-highlight: a coloured object whose highlight goes to display white (eq. 3-4),
// extended to several coloured lights. The highlight model's hook is
// shade_highlight. C++ twins: reference/models.cpp (same names).
#include "terms/highlight_blend.glsl"

// The two parts shared with the translucent model (docs/spec.md#42-translucent):
//   C1   = min([d + (1 - d) sum_l a_l c_l (N.L_l)+] C0, 1)
//   keep = prod_l (1 - s_l)
struct HighlightParts {
    vec3 C1;
    vec3 keep;
};

// C1 with a colour spectrum (docs/spec.md#73-spectral-colours): each light's
// diffuse share in its own C0 from the material's spectral table
// (passes/spectral_tables.h), d in D65's: d C0_D65 + (1 - d) sum_l a_l c_l (N.L) C0_l.
HighlightParts highlight_parts_spectral(Material mat, vec3 P, vec3 N, vec3 V) {
    int table = int(mat.spectral_table);
    vec3 diffuse = vec3(0.0);
    vec3 keep = vec3(1.0);
    for (int i = 0; i < LIGHT_LOOP_END; ++i) FOR_EACH_SAMPLE_OF_LIGHT(i, P, N, V, lobe_exponents(mat, i)) {
        LightSample light = light_sample_of(i, P, N);
        float NoL = dot(N, light.L);
        if (NoL <= 0.0) continue;  // no contribution where N.L <= 0
        diffuse += light.scale * NoL * m3055_material_texel(table + 1 + i).rgb;
        vec3 R = 2.0 * NoL * N - light.L;
        float one_minus_RoV = one_minus_cos(R, V);
        keep *= HIGHLIGHT_KEEP(mat.w, light, cos_between(R, V), one_minus_RoV, mat.m);
    }
    HighlightParts parts;
    parts.C1 = min(mat.d * m3055_material_texel(table).rgb + (1.0 - mat.d) * diffuse, vec3(1.0));
    parts.keep = keep;
    return parts;
}

HighlightParts highlight_parts(Material mat, vec3 P, vec3 N, vec3 V) {
#ifdef HAS_SPECTRAL_TABLES
    if (mat.spectral_table >= 0.0) return highlight_parts_spectral(mat, P, N, V);
#endif
    vec3 diffuse = vec3(0.0);
    vec3 keep = vec3(1.0);
    for (int i = 0; i < LIGHT_LOOP_END; ++i) FOR_EACH_SAMPLE_OF_LIGHT(i, P, N, V, lobe_exponents(mat, i)) {
        LightSample light = light_sample_of(i, P, N);
        float NoL = dot(N, light.L);
        if (NoL <= 0.0) continue;  // no contribution where N.L <= 0
        diffuse += light.scale * NoL;
        vec3 R = 2.0 * NoL * N - light.L;
        float one_minus_RoV = one_minus_cos(R, V);
        keep *= HIGHLIGHT_KEEP(mat.w, light, cos_between(R, V), one_minus_RoV, mat.m);
    }
    HighlightParts parts;
    parts.C1 = min((mat.d + (1.0 - mat.d) * diffuse) * mat.color, vec3(1.0));
    parts.keep = keep;
    return parts;
}

vec3 shade_highlight(Material mat, vec3 P, vec3 N, vec3 V) {
    HighlightParts parts = highlight_parts(mat, P, N, V);
    return highlight_to_white(parts.C1, parts.keep);
}
