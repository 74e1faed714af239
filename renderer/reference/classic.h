// The double-precision CPU twin of the seeds' classic models (docs/spec.md#5-classic-models,
// docs/models.md): one function per term, with the names of the GLSL terms in
// glsl/terms/ (diffuse.glsl, distributions.glsl, fresnel.glsl, anisotropic.glsl)
// and glsl/models/classic.glsl.
//
// Units. The lecture (seed 003) writes Lambert as I_diff = (N.L) K_diff (x) L_diff,
// i.e. a light of scale a_l c_l delivers the irradiance pi a_l c_l at normal
// incidence onto a BRDF f = K_diff / pi. Every BRDF-based term enters the same
// way, I = pi f (N.L) a_l c_l, so the "lecture-form" factors below are pi f (N.L)
// per unit K and unit light.
#pragma once

#include "reference/reference.h"

namespace m3055::ref {

// The microfacet model's choices of D and F, in the order of its table entry's
// "distribution" and "fresnel" choices (models/builtin_models.cpp; a test
// holds the two together): Material::choice gives the index.
enum class Distribution { blinn_phong, gaussian, beckmann, ggx };
enum class Fresnel { none, schlick, dielectric };

// ---- Diffuse: the factor of K_diff (x) L_diff ---------------------------------

// Lambert's cosine law (lecture, seed 003): (N.L)+.
double lambert(double NoL);
// Valve's Half-Lambert (Mitchell 2008, seed 004): ((N.L) 0.5 + 0.5)^2, lights the back too.
double half_lambert(double NoL);
// seed 004's code: N.L clamped at 0 first, ((N.L)+ 0.5 + 0.5)^2: 1/4 on the unlit side.
double half_lambert_clamped(double NoL);
// seed 004: Half-Lambert x 3/(4 pi), integrates to 1 over the sphere of directions.
double half_lambert_normalized(double NoL);
// Oren-Nayar's qualitative model (Oren & Nayar 1994; seed 003), times N.L:
//   (N.L)+ (A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta)),
//   alpha = max(theta_i, theta_o), beta = min(theta_i, theta_o),
//   A = 1 - 0.5 s^2/(s^2 + 0.33), B = 0.45 s^2/(s^2 + 0.09).
// Computed without trigonometry: cos(phi) sin(theta_i) sin(theta_o) = L.V - N.L N.V
// and sin(alpha) tan(beta) / (that product / cos phi) = 1 / max(N.L, N.V).
double oren_nayar(double sigma, double NoL, double NoV, double LoV);

// ---- Empirical specular lobes: the factor of K_spec (x) L_spec -----------------

// Phong 1975 (seed 001): ((R.V)+)^shininess.
double phong_lobe(double shininess, double RoV);
// Blinn 1977 (seed 003): ((N.H)+)^shininess.
double blinn_phong_lobe(double shininess, double NoH);

// ---- Microfacet normal distributions, normalized: integral D (N.h) dw = 1 -------

// Normalized Blinn-Phong (lecture): (n + 2)/(2 pi) (N.H)^n.
double blinn_phong_D(double n, double NoH);
// Torrance-Sparrow's Gaussian (lecture, seed 002): b exp(-(theta_h / m)^2), b = gaussian_norm(m).
double gaussian_D(double m, double b, double theta_h);
// (b: numeric::gaussian_norm, numeric/normalization.h.)
// Beckmann (Cook & Torrance 1982): the paper's delta(m, alpha) / pi,
// exp(-tan^2 a / m^2) / (pi m^2 cos^4 a).
double beckmann_normalized_D(double m, double NoH);
// GGX / Trowbridge-Reitz (Walter et al. 2007): a^2 / (pi ((N.H)^2 (a^2 - 1) + 1)^2),
// the denominator as sin^2 + a^2 cos^2 (seed 003 prints it unsquared: a typo).
double ggx_D(double alpha, double NoH);
// D of one microfacet lobe: m is the roughness, or the exponent n for blinn_phong.
double microfacet_D(Distribution distribution, double m, double NoH, double theta_h);

// ---- Fresnel --------------------------------------------------------------------

// F0 = ((n - 1)/(n + 1))^2, reflectance at normal incidence.
double schlick_F0(double ior);
// Schlick 1994: F0 + (1 - F0)(1 - cos)^5, cos = V.H.
double schlick_F(double F0, double VoH);
// Unpolarized dielectric Fresnel (Cook & Torrance 1982; seed 003 with its typos
// fixed: g^2 = n^2 + c^2 - 1, and + 1 in the last denominator):
//   F = 1/2 (g - c)^2/(g + c)^2 {1 + [c(g + c) - 1]^2 / [c(g - c) + 1]^2},  c = V.H.
double dielectric_F(double ior, double VoH);

// ---- Anisotropic ------------------------------------------------------------------

// The tangent frame on a surface (docs/models.md): T = normalize(axis x N), the
// direction of the grooves (around `axis`, like brushing on a lathe),
// B = N x T. Where N is within 1e-4 rad of +-axis (the poles), T falls back to
// normalize(e x N), e the coordinate axis least aligned with `axis`.
struct TangentFrame {
    dvec3 T;
    dvec3 B;
};
TangentFrame tangent_frame(const dvec3& axis, const dvec3& N);

// Ward 1992 (seed 002), lecture form pi f (N.L) with
//   f = exp(-((h.T/ax)^2 + (h.B/ay)^2) / (h.N)^2) / (4 pi ax ay sqrt(N.L N.V)),
// h = L + V (any length: the exponent is tan^2(theta_h)(cos^2 phi/ax^2 + sin^2 phi/ay^2)).
// Zero unless N.L > 0 and N.V > 0.
double ward_specular(double alpha_x, double alpha_y, double NoL, double NoV, double HoT, double HoB,
                     double HoN);

// ---- Models ---------------------------------------------------------------------------

// The classic models' hooks (reference/classic_models.cpp), namesakes of
// glsl/models/classic.glsl's: the diffuse factor of each diffuse model, and
// the specular colour of each model with a specular term.
ClassicDiffuseFn diffuse_lambert, diffuse_half_lambert, diffuse_half_lambert_clamped,
    diffuse_half_lambert_normalized, diffuse_oren_nayar, diffuse_minnaert;
ClassicSpecularFn specular_phong, specular_blinn_phong, specular_microfacet, specular_ward,
    specular_heidrich_seidel;
// Each classic model's hook (ClassicReflectFn, reference/reference.h), named
// NAME_reflect, is in classic_models.cpp; its table entry points at it.

// I_spec / L_spec, K_spec included (its hook with K_diff = 0), for unit N, L, V;
// zero for diffuse-only models and where N.L <= 0.
dvec3 classic_specular(const Material& material, const dvec3& N, const dvec3& L, const dvec3& V);
// The BRDF f(L, V) = (I_diff + I_spec) / (pi (N.L) L) for N.L > 0: what the
// reciprocity and energy tests integrate.
dvec3 classic_brdf(const Material& material, const dvec3& N, const dvec3& L, const dvec3& V);

// The lecture's equation at a point (seed 003), the classic family's composer:
//   I = L_glob K_amb + L_emi + sum_k C_spot,k { a_k ambient_k K_amb + att_k (I_diff,k + I_spec,k) }.
// An area light's nodes add their I_diff + I_spec and no ambient (it has none).
dvec3 shade_classic(const Material& material, const LitLights& lights, const SurfacePoint& point,
                    const dvec3& global_ambient);
// The same for a plain list of lights (every type, no shadows).
dvec3 shade_classic(const Material& material, const std::vector<Light>& lights, const SurfacePoint& point,
                    const dvec3& global_ambient);

}  // namespace m3055::ref
