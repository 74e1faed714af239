// SPEC 4.3 and 4.4: metals. C = { d + sum_l a_l c_l sum_j w_j lobe_j } C0 with
//   metal        (eq. 12): lobe = delta(m_j, alpha) G / (N.V)   (Beckmann mixture)
//   metal_blinn  (eq. 15): lobe = ((N.H)+)^n_j
//   metal_phong  (eq. 16): lobe = ((R.V)+)^n_j
// F = C0 (the paper's assumption 3), so no Fresnel and no pi. Not clamped:
// the display clamps. C++ twin: ref::shade_opaque (metal family).

// sum_j w_j lobe_j for light i, over the light's own lobes or the material's.
float metal_lobe_sum(Material mat, int i, vec3 N, vec3 V, vec3 L, float NoL, float NoV) {
    int own = light_lobe_count(i, mat);
    int count = own > 0 ? own : mat.lobe_count;
    vec3 H = L + V;  // unnormalized: one_minus_cos does not need it unit
    // L = -V exactly (light opposite the view; lit only where N.V < 0, i.e. by
    // rounding at a silhouette) leaves H undefined and one_minus_cos(N, 0)
    // NaN: take H = N, as ref::half_vector does.
    if (dot(H, H) == 0.0) H = N;
    float one_minus_NoH = one_minus_cos(N, H);
    float sum = 0.0;
#ifdef HAS_METAL
    if (mat.model == MODEL_METAL) {
        // V.H = |L + V| / 2 for unit L, V: never negative, and free of the
        // cancellation of dot(V, normalize(L + V)) when L is nearly -V, which
        // gave V.H ~ 0 and G / N.V ~ 1e30. 0 (the fallback above) gives no lobe.
        float VoH = 0.5 * length(L + V);
        H = normalize(H);
        float NoH = max(dot(N, H), 0.0);
        for (int j = 0; j < count; ++j) {
            vec2 lobe = own > 0 ? light_lobe(i, j) : mat.lobe[j];
            sum += lobe.x * beckmann_D(lobe.y, NoH, one_minus_NoH);
        }
        return sum * ct_G_over_NoV(NoH, NoV, NoL, VoH);
    }
#endif
#if defined(HAS_METAL_BLINN) || defined(HAS_METAL_PHONG)
    // metal_blinn reads N.H, metal_phong R.V.
    vec3 R = 2.0 * NoL * N - L;
#if !defined(HAS_METAL_PHONG)
    float c = cos_between(N, H), delta = one_minus_NoH;
#elif !defined(HAS_METAL_BLINN)
    float c = cos_between(R, V), delta = one_minus_cos(R, V);
#else
    bool blinn = mat.model == MODEL_METAL_BLINN;
    float c = blinn ? cos_between(N, H) : cos_between(R, V);
    float delta = blinn ? one_minus_NoH : one_minus_cos(R, V);
#endif
    for (int j = 0; j < count; ++j) {
        vec2 lobe = own > 0 ? light_lobe(i, j) : mat.lobe[j];
        sum += lobe.x * pow_cos(c, delta, lobe.y);
    }
#endif
    return sum;
}

vec3 shade_metal(Material mat, vec3 P, vec3 N, vec3 V) {
    float NoV = max(dot(N, V), 0.0);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < LIGHT_LOOP_END; ++i) {
        LightSample light = light_sample(i, P);
        float NoL = dot(N, light.L);
        if (NoL <= 0.0) continue;  // no contribution where N.L <= 0
        sum += light.scale * metal_lobe_sum(mat, i, N, V, light.L, NoL, NoV);
    }
    return (mat.d + sum) * mat.color;
}
