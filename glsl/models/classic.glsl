// docs/spec.md#5-classic-models: the seeds' classic models in the lecture's shading equation (seed 003):
//   I = L_glob K_amb + L_emi + sum_k C_spot,k { I_amb,k + att_k (I_diff,k + I_spec,k) }
// with I_amb,k = a_k ambient_k (x) K_amb, I_diff,k = diffuse(N.L...) K_diff (x) a_k c_k,
// I_spec,k = specular(...) K_spec (x) a_k c_k. light_sample's scale is
// a_k c_k att_k C_spot,k and its spot C_spot,k. docs/models.md lists the models.
// Each model has two hooks: diffuse_NAME, the factor of K_diff (Lambert's for
// the models with a specular term), and specular_NAME, I_spec / L_spec.
// C++ twins: reference/classic_models.cpp (same names).
#include "terms/diffuse.glsl"
#include "terms/phong_lobes.glsl"
#include "terms/distributions.glsl"
#include "terms/fresnel.glsl"
#include "terms/ct_geometry.glsl"
#include "terms/anisotropic.glsl"
#include "terms/conductor_table.glsl"

uniform vec3 u_global_ambient;             // L_glob
uniform vec3 u_light_ambient[MAX_LIGHTS];  // a_k ambient_k (L_amb,k)

// ---- Diffuse hooks: the factor of K_diff (x) L_diff -------------------------------

float diffuse_lambert(Material mat, float NoL, float NoV, float LoV) {
    return lambert(NoL);
}

float diffuse_half_lambert(Material mat, float NoL, float NoV, float LoV) {
    return half_lambert(NoL);
}

float diffuse_half_lambert_clamped(Material mat, float NoL, float NoV, float LoV) {
    return half_lambert_clamped(NoL);
}

float diffuse_half_lambert_normalized(Material mat, float NoL, float NoV, float LoV) {
    return half_lambert_normalized(NoL);
}

float diffuse_oren_nayar(Material mat, float NoL, float NoV, float LoV) {
    return oren_nayar(mat.sigma, NoL, NoV, LoV);
}

// Minnaert 1941 (BRDF Explorer's minnaert.brdf): f = (k + 1)/(2 pi) (N.L N.V)^(k - 1),
// so pi f (N.L) = (k + 1)/2 (N.L)^k (N.V)^(k - 1); k = 1 is Lambert, k < 1
// brightens the limb (the Moon), k > 1 darkens it. N.V is floored at 1e-4:
// (N.V)^(k - 1) grows without bound at the silhouette for k < 1.
float diffuse_minnaert(Material mat, float NoL, float NoV, float LoV) {
    if (NoL <= 0.0) return 0.0;
    float k = mat.minnaert_k;
    return 0.5 * (k + 1.0) * pow(NoL, k) * pow(max(NoV, 1e-4), k - 1.0);
}

// ---- Specular hooks: I_spec / L_spec, K_spec included, 0 where N.L <= 0 ---------

vec3 specular_phong(Material mat, vec3 N, vec3 L, vec3 V, float NoL, float NoV) {
    if (NoL <= 0.0) return vec3(0.0);
    vec3 R = 2.0 * NoL * N - L;
    return phong_lobe(mat.shininess, cos_between(R, V), one_minus_cos(R, V)) * mat.ks;
}

vec3 specular_blinn_phong(Material mat, vec3 N, vec3 L, vec3 V, float NoL, float NoV) {
    if (NoL <= 0.0) return vec3(0.0);
    vec3 H = L + V;
    if (dot(H, H) == 0.0) H = N;
    return blinn_phong_lobe(mat.shininess, cos_between(N, H), one_minus_cos(N, H)) * mat.ks;
}

// pi f (N.L) for f = D G F / (4 N.L N.V), D the weighted sum of the lobes:
// pi sum_j w_j D_j G F / (4 N.V), G / N.V from ct_G_over_NoV (finite at N.V = 0).
float microfacet_lobe(Material mat, vec3 N, vec3 L, vec3 V, float NoL, float NoV) {
    vec3 H = L + V;
    if (dot(H, H) == 0.0) H = N;  // L = -V: no half vector (as ref::half_vector)
    float one_minus_NoH = one_minus_cos(N, H);
    float VoH = 0.5 * length(L + V);  // V.H for unit L, V, free of cancellation
    H = normalize(H);
    float NoH = max(dot(N, H), 0.0);
    float theta_h = atan(length(cross(N, H)), dot(N, H));
    float D = 0.0;
    for (int j = 0; j < mat.lobes_count; ++j)
        D += mat.lobes[j].x * microfacet_D(mat.distribution, mat.lobes[j].y, mat.lobe_norm[j], NoH,
                                           one_minus_NoH, theta_h);
    if (D == 0.0) return 0.0;
    float F = 1.0;
    if (mat.fresnel == FRESNEL_SCHLICK) F = schlick_F(schlick_F0(mat.ior), VoH);
    if (mat.fresnel == FRESNEL_DIELECTRIC) F = dielectric_F(mat.ior, VoH);
    return PI * D * ct_G_over_NoV(NoH, NoV, NoL, VoH) * F / 4.0;
}

vec3 specular_microfacet(Material mat, vec3 N, vec3 L, vec3 V, float NoL, float NoV) {
    if (NoL <= 0.0) return vec3(0.0);
    return microfacet_lobe(mat, N, L, V, NoL, NoV) * mat.ks;
}

vec3 specular_ward(Material mat, vec3 N, vec3 L, vec3 V, float NoL, float NoV) {
    if (NoL <= 0.0) return vec3(0.0);
    vec3 T, B;
    tangent_frame(mat.axis, N, T, B);
    vec3 h = L + V;
    return ward_specular(mat.alpha_x, mat.alpha_y, NoL, NoV, dot(h, T), dot(h, B), dot(h, N)) * mat.ks;
}

// Heidrich & Seidel 1998 (seed 002): ((sin(L,T) sin(V,T) - cos(L,T) cos(V,T))+)^n
// = (cos x)^n with x = pi - angle(L,T) - angle(V,T). The angles come from
// atan(|a x T|, a.T), so 1 - cos x = 2 sin^2(x/2) stays accurate for n = 10000.
float heidrich_seidel_lobe(float n, float angle_LT, float angle_VT) {
    float x = PI - angle_LT - angle_VT;
    float s = sin(0.5 * x);
    return pow_cos(cos(x), 2.0 * s * s, n);
}

vec3 specular_heidrich_seidel(Material mat, vec3 N, vec3 L, vec3 V, float NoL, float NoV) {
    if (NoL <= 0.0) return vec3(0.0);
    vec3 T, B;
    tangent_frame(mat.axis, N, T, B);
    return heidrich_seidel_lobe(mat.shininess, atan(length(cross(L, T)), dot(L, T)),
                                atan(length(cross(V, T)), dot(V, T))) * mat.ks;
}

// ---- The family: the lecture's equation over the lights ---------------------------
// classic_diffuse and classic_specular (generated from the model table) pick
// the material's hooks.

// A classic material with a spectral table (passes/spectral_tables.h): a
// microfacet conductor (docs/spec.md#72-measured-metals), whose K_spec F is the
// metal's C0 for each light at V.H, and/or a kd_spectrum (#73-spectral-colours),
// whose K_diff is its colour under each light; both read from the table.
vec3 shade_classic_spectral(Material mat, vec3 P, vec3 N, vec3 V) {
    int table = int(mat.spectral_table);
    vec4 head = m3055_material_texel(table);
    int samples = int(head.a);  // the conductor's texels a light; 0: ks as given
    int kd_at = int(head.r);    // kd's colours a light from here; < 0: kd as given
    if (samples > 0) {
        mat.ks = vec3(1.0);
        mat.fresnel = FRESNEL_NONE;  // F is in the table
    }
    vec3 I = u_global_ambient * mat.ka + mat.emission;
    float NoV = max(dot(N, V), 0.0);
    for (int i = 0; i < LIGHT_LOOP_END; ++i) FOR_EACH_SAMPLE_OF_LIGHT(i, P, N, V, lobe_exponents(mat, i)) {
        LightSample light = light_sample_of(i, P, N);
        I += light.spot * u_light_ambient[i] * mat.ka;  // spot-shaped, not attenuated
        float NoL = dot(N, light.L);
        float diffuse = classic_diffuse(mat, NoL, NoV, dot(light.L, V));
        vec3 kd = kd_at >= 0 ? m3055_material_texel(table + kd_at + i).rgb : mat.kd;
        vec3 c0 = samples > 0 ? conductor_c0(table + 1 + i * samples, samples, 0.5 * length(light.L + V)) : vec3(1.0);
        I += light.scale * (diffuse * kd + classic_specular(mat, N, light.L, V, NoL, NoV) * c0);
    }
    return I;
}

vec3 shade_classic(Material mat, vec3 P, vec3 N, vec3 V) {
    if (mat.spectral_table >= 0.0) return shade_classic_spectral(mat, P, N, V);
    vec3 I = u_global_ambient * mat.ka + mat.emission;
    float NoV = max(dot(N, V), 0.0);
    for (int i = 0; i < LIGHT_LOOP_END; ++i) FOR_EACH_SAMPLE_OF_LIGHT(i, P, N, V, lobe_exponents(mat, i)) {
        LightSample light = light_sample_of(i, P, N);
        I += light.spot * u_light_ambient[i] * mat.ka;  // spot-shaped, not attenuated
        float NoL = dot(N, light.L);
        float diffuse = classic_diffuse(mat, NoL, NoV, dot(light.L, V));
        I += light.scale * (diffuse * mat.kd + classic_specular(mat, N, light.L, V, NoL, NoV));
    }
    return I;
}
