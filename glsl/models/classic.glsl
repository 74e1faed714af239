// SPEC 5: the seeds' classic models in the lecture's shading equation (seed 003):
//   I = L_glob K_amb + L_emi + sum_k C_spot,k { I_amb,k + att_k (I_diff,k + I_spec,k) }
// with I_amb,k = a_k ambient_k (x) K_amb, I_diff,k = diffuse(N.L...) K_diff (x) a_k c_k,
// I_spec,k = specular(...) K_spec (x) a_k c_k. light_sample's scale is
// a_k c_k att_k C_spot,k and its spot C_spot,k. docs/models.md lists the models.
// C++ twin: ref::shade_classic (reference/classic_models.cpp).
#include "terms/diffuse.glsl"
#include "terms/phong_lobes.glsl"
#include "terms/distributions.glsl"
#include "terms/fresnel.glsl"
#include "terms/ct_geometry.glsl"
#include "terms/anisotropic.glsl"

uniform vec3 u_global_ambient;             // L_glob
uniform vec3 u_light_ambient[MAX_LIGHTS];  // a_k ambient_k (L_amb,k)

// The diffuse factor: the diffuse models' own term, Lambert for the specular models.
float classic_diffuse(Material mat, float NoL, float NoV, float LoV) {
#ifdef HAS_HALF_LAMBERT
    if (mat.model == MODEL_HALF_LAMBERT) return half_lambert(NoL);
#endif
#ifdef HAS_HALF_LAMBERT_CLAMPED
    if (mat.model == MODEL_HALF_LAMBERT_CLAMPED) return half_lambert_clamped(NoL);
#endif
#ifdef HAS_HALF_LAMBERT_NORMALIZED
    if (mat.model == MODEL_HALF_LAMBERT_NORMALIZED) return half_lambert_normalized(NoL);
#endif
#ifdef HAS_OREN_NAYAR
    if (mat.model == MODEL_OREN_NAYAR) return oren_nayar(mat.sigma, NoL, NoV, LoV);
#endif
    return lambert(NoL);
}

#ifdef HAS_MICROFACET
// pi f (N.L) for f = D G F / (4 N.L N.V), D the weighted sum of the lobes:
// pi sum_j w_j D_j G F / (4 N.V), G / N.V from ct_G_over_NoV (finite at N.V = 0).
float microfacet_specular(Material mat, vec3 N, vec3 L, vec3 V, float NoL, float NoV) {
    vec3 H = L + V;
    if (dot(H, H) == 0.0) H = N;  // L = -V: no half vector (as ref::half_vector)
    float one_minus_NoH = one_minus_cos(N, H);
    float VoH = 0.5 * length(L + V);  // V.H for unit L, V, free of cancellation
    H = normalize(H);
    float NoH = max(dot(N, H), 0.0);
    float theta_h = atan(length(cross(N, H)), dot(N, H));
    float D = 0.0;
    for (int j = 0; j < mat.lobe_count; ++j)
        D += mat.lobe[j].x * microfacet_D(mat.distribution, mat.lobe[j].y, mat.lobe_norm[j], NoH,
                                          one_minus_NoH, theta_h);
    if (D == 0.0) return 0.0;
    float F = 1.0;
    if (mat.fresnel == FRESNEL_SCHLICK) F = schlick_F(schlick_F0(mat.ior), VoH);
    if (mat.fresnel == FRESNEL_DIELECTRIC) F = dielectric_F(mat.ior, VoH);
    return PI * D * ct_G_over_NoV(NoH, NoV, NoL, VoH) * F / 4.0;
}
#endif

// I_spec / L_spec, K_spec included; 0 where N.L <= 0 and for the diffuse models.
vec3 classic_specular(Material mat, vec3 N, vec3 L, vec3 V, float NoL, float NoV) {
    if (NoL <= 0.0 || mat.model < MODEL_PHONG) return vec3(0.0);
    float lobe = 0.0;
#ifdef HAS_PHONG
    if (mat.model == MODEL_PHONG) {
        vec3 R = 2.0 * NoL * N - L;
        lobe = phong_lobe(mat.shininess, cos_between(R, V), one_minus_cos(R, V));
    }
#endif
#ifdef HAS_BLINN_PHONG
    if (mat.model == MODEL_BLINN_PHONG) {
        vec3 H = L + V;
        if (dot(H, H) == 0.0) H = N;
        lobe = blinn_phong_lobe(mat.shininess, cos_between(N, H), one_minus_cos(N, H));
    }
#endif
#ifdef HAS_MICROFACET
    if (mat.model == MODEL_MICROFACET) lobe = microfacet_specular(mat, N, L, V, NoL, NoV);
#endif
#if defined(HAS_WARD) || defined(HAS_HEIDRICH_SEIDEL)
    if (mat.model == MODEL_WARD || mat.model == MODEL_HEIDRICH_SEIDEL) {
        vec3 T, B;
        tangent_frame(mat.axis, N, T, B);
#ifdef HAS_WARD
        if (mat.model == MODEL_WARD) {
            vec3 h = L + V;
            lobe = ward_specular(mat.alpha_x, mat.alpha_y, NoL, NoV, dot(h, T), dot(h, B), dot(h, N));
        }
#endif
#ifdef HAS_HEIDRICH_SEIDEL
        if (mat.model == MODEL_HEIDRICH_SEIDEL)
            lobe = heidrich_seidel_lobe(mat.shininess, atan(length(cross(L, T)), dot(L, T)),
                                        atan(length(cross(V, T)), dot(V, T)));
#endif
    }
#endif
    return lobe * mat.ks;
}

vec3 shade_classic(Material mat, vec3 P, vec3 N, vec3 V) {
    vec3 I = u_global_ambient * mat.ka + mat.emission;
    float NoV = max(dot(N, V), 0.0);
    for (int i = 0; i < LIGHT_LOOP_END; ++i) {
        LightSample light = light_sample(i, P);
        I += light.spot * u_light_ambient[i] * mat.ka;  // spot-shaped, not attenuated
        float NoL = dot(N, light.L);
        float diffuse = classic_diffuse(mat, NoL, NoV, dot(light.L, V));
        I += light.scale * (diffuse * mat.kd + classic_specular(mat, N, light.L, V, NoL, NoV));
    }
    return I;
}
