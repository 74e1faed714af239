// Burley's principled BRDF: B. Burley, "Physically-Based Shading at Disney",
// SIGGRAPH 2012 course notes (Practical Physically-Based Shading in Film and
// Game Production), and its reference implementation, BRDF Explorer's
// src/brdfs/disney.brdf (github.com/wdas/brdf). docs/models.md#principled-burleys-principled-brdf.
//
// In the classic family (models/classic.glsl), on its scale: a light adds
// pi f (N.L) a c. diffuse_principled is the factor of K_diff, which for this
// model is the base colour (its derived value kd); specular_principled is the
// rest, coloured: sheen, the anisotropic GTR2 specular and the GTR1 clear coat.
// The base colour is linear: disney.brdf's mon2lin (x^2.2) is not applied.
// C++ twins: reference/principled.cpp (same names).
#include "models/classic.glsl"
#include "terms/anisotropic.glsl"

// Schlick's Fresnel weight (1 - u)^5 (Schlick 1994), u clamped to [0, 1]:
// Burley's F_L, F_V (u = N.L, N.V) and F_H (u = L.H). Absolute error a few
// float ulps: 1 - u is exact for u in [0.5, 1] (Sterbenz).
float principled_schlick_weight(float u) {
    float m = clamp(1.0 - u, 0.0, 1.0);
    float m2 = m * m;
    return m2 * m2 * m;
}

// The hue and saturation of the base colour: C / lum(C), lum = 0.3 R + 0.6 G +
// 0.1 B (disney.brdf's luminance approximation); white for a black base colour.
vec3 principled_tint(vec3 base_color) {
    float lum = 0.3 * base_color.r + 0.6 * base_color.g + 0.1 * base_color.b;
    return lum > 0.0 ? base_color / lum : vec3(1.0);
}

// Burley 2012, the diffuse model: Fresnel-like factors with retro-reflection,
//   (1 + (F_D90 - 1) F_L)(1 + (F_D90 - 1) F_V),  F_D90 = 0.5 + 2 r cos^2(theta_d).
// 1 at normal incidence, from 0.5 (smooth) to 2.5 (rough) at grazing.
float principled_diffuse_fresnel(float roughness, float LoH2, float FL, float FV) {
    float fd90 = 0.5 + 2.0 * LoH2 * roughness;
    return mix(1.0, fd90, FL) * mix(1.0, fd90, FV);
}

// Burley 2012, subsurface: a lobe after Hanrahan and Krueger's (1993)
// BRDF approximation of an isotropic BSSRDF, 1.25 scaling to keep the albedo:
//   ss = 1.25 (F_ss (1/(N.L + N.V) - 0.5) + 0.5),  F_ss90 = r cos^2(theta_d),
// returned as ss (N.L), whose N.L / (N.L + N.V) stays <= 1 where 1/(N.L + N.V)
// grows without bound (terminator and silhouette together). N.L > 0.
float principled_subsurface(float roughness, float LoH2, float FL, float FV, float NoL, float NoV) {
    float fss90 = LoH2 * roughness;
    float fss = mix(1.0, fss90, FL) * mix(1.0, fss90, FV);
    return 1.25 * (fss * (NoL / (NoL + NoV) - 0.5 * NoL) + 0.5 * NoL);
}

// Burley 2012, the anisotropic GTR2 (GGX) distribution (its appendix),
//   D = 1 / (pi ax ay ((h.T/ax)^2 + (h.B/ay)^2 + (h.N)^2)^2),
// normalized (integral D (N.h) dw = 1). The sum is tan^2-free and has no
// cancellation near the peak (h.T, h.B are small components, not 1 - cos).
float principled_gtr2_aniso(float HoT, float HoB, float NoH, float ax, float ay) {
    float x = HoT / ax, y = HoB / ay;
    float t = x * x + y * y + NoH * NoH;
    return 1.0 / (PI * ax * ay * t * t);
}

// Burley 2012, GTR with gamma = 1 (Berry's distribution; eq. 4 as revised), the
// clear coat's, for alpha in [0.001, 0.1] (clearcoat_gloss 1 ... 0):
//   D = (a^2 - 1) / (pi ln(a^2) (1 + (a^2 - 1) cos^2 theta_h)).
// The bracket is written sin^2 + a^2 cos^2 with sin^2 from |N x h|^2: near the
// peak cos theta_h holds only ~6e-8 in float, and any 1 - cos^2 form must
// resolve a^2 = 1e-6 there (disney.brdf's 1 + (a^2 - 1) cos^2 is off by up to
// ~10 % within a fraction of a degree of the gloss-1 peak; this form stays
// within 2.4e-4 of the double reference).
float principled_gtr1(float sin2_h, float cos2_h, float alpha) {
    float a2 = alpha * alpha;
    return (a2 - 1.0) / (PI * log(a2) * (sin2_h + a2 * cos2_h));
}

// Smith's masking for the anisotropic GGX, separable, divided by 2 (N.v) as
// disney.brdf writes it (G1 = 1 / (1 + Lambda), Lambda of GGX: Heitz 2014):
//   G1(v) / (2 N.v) = 1 / (N.v + sqrt((v.T ax)^2 + (v.B ay)^2 + (N.v)^2)),
// so G1(L) G1(V) / (4 N.L N.V) is the product of two. Finite at N.v = 0.
float principled_smith_ggx_aniso(float NoV, float VoT, float VoB, float ax, float ay) {
    float x = VoT * ax, y = VoB * ay;
    return 1.0 / (NoV + sqrt(x * x + y * y + NoV * NoV));
}

// The isotropic form (Walter et al. 2007), for the clear coat's fixed alpha_g = 0.25:
//   G1(v) / (2 N.v) = 1 / (N.v + sqrt(a^2 + (N.v)^2 - a^2 (N.v)^2)).
float principled_smith_ggx(float NoV, float alpha) {
    float a2 = alpha * alpha;
    float b = NoV * NoV;
    return 1.0 / (NoV + sqrt(a2 + b - a2 * b));
}

// ---- The hooks --------------------------------------------------------------------

// pi f_d (N.L) / base colour: (1 - metallic) mix(diffuse, subsurface) (N.L),
// cos^2(theta_d) = (L.H)^2 = (1 + L.V) / 2 for unit L, V.
float diffuse_principled(Material mat, float NoL, float NoV, float LoV) {
    if (NoL <= 0.0) return 0.0;
    NoV = max(NoV, 0.0);
    float LoH2 = clamp(0.5 + 0.5 * LoV, 0.0, 1.0);
    float FL = principled_schlick_weight(NoL), FV = principled_schlick_weight(NoV);
    float fd = principled_diffuse_fresnel(mat.roughness, LoH2, FL, FV) * NoL;
    float ss = principled_subsurface(mat.roughness, LoH2, FL, FV, NoL, NoV);
    return (1.0 - mat.metallic) * mix(fd, ss, mat.subsurface);
}

// pi (N.L) times the sheen (1 - metallic) F_H sheen C_sheen, the specular
// D_s F_s G_s and the clear coat 0.25 clearcoat D_r F_r G_r, where
//   C_spec0 = mix(0.08 specular mix(1, C_tint, specular_tint), C, metallic),
//   F_s = mix(C_spec0, 1, F_H), F_r = mix(0.04, 1, F_H), C_sheen = mix(1, C_tint, sheen_tint),
//   alpha_x = max(0.001, r^2 / aspect), alpha_y = max(0.001, r^2 aspect),
//   aspect = sqrt(1 - 0.9 anisotropic), clear coat alpha = mix(0.1, 0.001, clearcoat_gloss).
// The sheen has no 1/pi (as in disney.brdf). L.H = |L + V| / 2, free of cancellation.
vec3 specular_principled(Material mat, vec3 N, vec3 L, vec3 V, float NoL, float NoV) {
    if (NoL <= 0.0) return vec3(0.0);
    NoV = max(NoV, 0.0);
    vec3 T, B;
    tangent_frame(mat.axis, N, T, B);
    vec3 H = L + V;
    float LoH = 0.5 * length(H);
    H = dot(H, H) > 0.0 ? normalize(H) : N;  // L = -V: no half vector; N, as the other models
    float NoH = dot(N, H);
    vec3 NxH = cross(N, H);
    float FH = principled_schlick_weight(LoH);

    vec3 tint = principled_tint(mat.base_color);
    vec3 sheen = (1.0 - mat.metallic) * FH * mat.sheen * mix(vec3(1.0), tint, mat.sheen_tint);

    float aspect = sqrt(1.0 - 0.9 * mat.anisotropic);
    float r2 = mat.roughness * mat.roughness;
    float ax = max(0.001, r2 / aspect), ay = max(0.001, r2 * aspect);
    float Ds = principled_gtr2_aniso(dot(H, T), dot(H, B), NoH, ax, ay);
    float Gs = principled_smith_ggx_aniso(NoL, dot(L, T), dot(L, B), ax, ay) *
               principled_smith_ggx_aniso(NoV, dot(V, T), dot(V, B), ax, ay);
    vec3 spec0 = mix(mat.specular * 0.08 * mix(vec3(1.0), tint, mat.specular_tint), mat.base_color, mat.metallic);
    vec3 specular = Ds * Gs * mix(spec0, vec3(1.0), FH);

    float Dr = principled_gtr1(dot(NxH, NxH), NoH * NoH, mix(0.1, 0.001, mat.clearcoat_gloss));
    float Gr = principled_smith_ggx(NoL, 0.25) * principled_smith_ggx(NoV, 0.25);
    float coat = 0.25 * mat.clearcoat * Dr * Gr * mix(0.04, 1.0, FH);

    return (PI * NoL) * (sheen + specular + vec3(coat));
}
