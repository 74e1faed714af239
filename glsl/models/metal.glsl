// docs/spec.md#43-metal and #44-cheap-metals: metals. C = { d + sum_l a_l c_l sum_j w_j lobe_j } C0 with
//   metal        (eq. 12): lobe = delta(m_j, alpha) G / (N.V)   (Beckmann mixture)
//   metal_blinn  (eq. 15): lobe = ((N.H)+)^n_j
//   metal_phong  (eq. 16): lobe = ((R.V)+)^n_j
// F = C0 (the paper's assumption 3), so no Fresnel and no pi. Not clamped:
// the display clamps. Each model's hook gives sum_j w_j lobe_j for one light,
// over the light's own lobes (Fig. 11) or the material's; metal_lobe_sum
// (generated from the model table) picks the hook. C++ twins: reference/models.cpp.
#include "terms/beckmann.glsl"
#include "terms/ct_geometry.glsl"
#include "terms/conductor_table.glsl"

// L + V, or N where L = -V exactly (light opposite the view; lit only where
// N.V < 0, i.e. by rounding at a silhouette): there H is undefined and
// one_minus_cos(N, 0) NaN. ref::half_vector does the same.
vec3 half_vector_or_normal(vec3 L, vec3 V, vec3 N) {
    vec3 H = L + V;  // unnormalized: one_minus_cos does not need it unit
    if (dot(H, H) == 0.0) H = N;
    return H;
}

// metal (eq. 12-13): sum_j w_j delta(m_j, alpha) G / (N.V).
float beckmann_lobe_sum(Material mat, int i, vec3 N, vec3 V, vec3 L, float NoL, float NoV) {
    int own = light_lobe_count(i, LIGHT_LOBES_BECKMANN);
    int count = own > 0 ? own : mat.lobes_count;
    vec3 H = half_vector_or_normal(L, V, N);
    float one_minus_NoH = one_minus_cos(N, H);
    // V.H = |L + V| / 2 for unit L, V: never negative, and free of the
    // cancellation of dot(V, normalize(L + V)) when L is nearly -V, which
    // gave V.H ~ 0 and G / N.V ~ 1e30. 0 (the fallback above) gives no lobe.
    float VoH = 0.5 * length(L + V);
    H = normalize(H);
    float NoH = max(dot(N, H), 0.0);
    float sum = 0.0;
    for (int j = 0; j < count; ++j) {
        vec2 lobe = own > 0 ? light_lobe(i, j) : mat.lobes[j];
        sum += lobe.x * beckmann_D(lobe.y, NoH, one_minus_NoH);
    }
    return sum * ct_G_over_NoV(NoH, NoV, NoL, VoH);
}

// sum_j w_j (c+)^n_j from c = cos and delta = 1 - cos, over light i's own
// exponent lobes or the material's.
float exponent_lobe_sum(Material mat, int i, float c, float delta) {
    int own = light_lobe_count(i, LIGHT_LOBES_EXPONENT);
    int count = own > 0 ? own : mat.lobes_count;
    float sum = 0.0;
    for (int j = 0; j < count; ++j) {
        vec2 lobe = own > 0 ? light_lobe(i, j) : mat.lobes[j];
        sum += lobe.x * pow_cos(c, delta, lobe.y);
    }
    return sum;
}

// metal_blinn (eq. 15): lobes on N.H.
float blinn_lobe_sum(Material mat, int i, vec3 N, vec3 V, vec3 L, float NoL, float NoV) {
    vec3 H = half_vector_or_normal(L, V, N);
    return exponent_lobe_sum(mat, i, cos_between(N, H), one_minus_cos(N, H));
}

// metal_phong (eq. 16): lobes on R.V.
float phong_lobe_sum(Material mat, int i, vec3 N, vec3 V, vec3 L, float NoL, float NoV) {
    vec3 R = 2.0 * NoL * N - L;
    return exponent_lobe_sum(mat, i, cos_between(R, V), one_minus_cos(R, V));
}

// A measured metal: d C0_D65 + sum_l a_l c_l lobes_l C0_l(V.H), C0_l from the
// light's spectrum and the metal's n(lambda), k(lambda) (eq. 2 per pair; with
// "fresnel": "full", eq. 19 at the angle V.H).
vec3 shade_conductor(Material mat, vec3 P, vec3 N, vec3 V) {
    int table = int(mat.spectral_table);
    vec4 head = m3055_material_texel(table);  // rgb: the background's C0; a: samples per light
    int samples = int(head.a);
    float NoV = max(dot(N, V), 0.0);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < LIGHT_LOOP_END; ++i) FOR_EACH_SAMPLE_OF_LIGHT(i, P, N, V, lobe_exponents(mat, i)) {
        LightSample light = light_sample_of(i, P, N);
        float NoL = dot(N, light.L);
        if (NoL <= 0.0) continue;  // no contribution where N.L <= 0
        float VoH = 0.5 * length(light.L + V);  // as beckmann_lobe_sum: |L + V| / 2
        vec3 c0 = conductor_c0(table + 1 + i * samples, samples, VoH);
        sum += light.scale * metal_lobe_sum(mat, i, N, V, light.L, NoL, NoV) * c0;
    }
    return mat.d * head.rgb + sum;
}

// The metal family: (d + sum_l a_l c_l lobes_l) C0, lights with N.L > 0 only.
vec3 shade_metal(Material mat, vec3 P, vec3 N, vec3 V) {
#ifdef HAS_SPECTRAL_TABLES
    if (mat.spectral_table >= 0.0) return shade_conductor(mat, P, N, V);
#endif
    float NoV = max(dot(N, V), 0.0);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < LIGHT_LOOP_END; ++i) FOR_EACH_SAMPLE_OF_LIGHT(i, P, N, V, lobe_exponents(mat, i)) {
        LightSample light = light_sample_of(i, P, N);
        float NoL = dot(N, light.L);
        if (NoL <= 0.0) continue;  // no contribution where N.L <= 0
        sum += light.scale * metal_lobe_sum(mat, i, N, V, light.L, NoL, NoV);
    }
    return (mat.d + sum) * mat.color;
}
