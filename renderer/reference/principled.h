// The double-precision twin of glsl/models/principled.glsl: Burley's principled
// BRDF (Burley 2012, "Physically-Based Shading at Disney"; BRDF Explorer's
// src/brdfs/disney.brdf), one function per term with the GLSL's names, and the
// model's two classic hooks. docs/models.md#principled-burleys-principled-brdf.
#pragma once

#include "reference/reference.h"

namespace m3055::ref {

// Schlick's weight (1 - u)^5, u clamped to [0, 1]: F_L, F_V, F_H.
double principled_schlick_weight(double u);
// The base colour's hue and saturation, C / (0.3 R + 0.6 G + 0.1 B); white for black.
dvec3 principled_tint(const dvec3& base_color);
// (1 + (F_D90 - 1) F_L)(1 + (F_D90 - 1) F_V), F_D90 = 0.5 + 2 r cos^2(theta_d).
double principled_diffuse_fresnel(double roughness, double LoH2, double FL, double FV);
// The Hanrahan-Krueger-like subsurface lobe times N.L:
// 1.25 (F_ss (1/(N.L + N.V) - 0.5) + 0.5) N.L, F_ss90 = r cos^2(theta_d); N.L > 0.
double principled_subsurface(double roughness, double LoH2, double FL, double FV, double NoL, double NoV);
// Anisotropic GTR2: 1 / (pi ax ay ((h.T/ax)^2 + (h.B/ay)^2 + (h.N)^2)^2).
double principled_gtr2_aniso(double HoT, double HoB, double NoH, double ax, double ay);
// GTR1: (a^2 - 1) / (pi ln(a^2) (sin^2 + a^2 cos^2)) of theta_h, for alpha in (0, 1).
double principled_gtr1(double sin2_h, double cos2_h, double alpha);
// Smith G1(v) / (2 N.v) of the anisotropic GGX: 1 / (N.v + sqrt((v.T ax)^2 + (v.B ay)^2 + (N.v)^2)).
double principled_smith_ggx_aniso(double NoV, double VoT, double VoB, double ax, double ay);
// Its isotropic form: 1 / (N.v + sqrt(a^2 + (N.v)^2 - a^2 (N.v)^2)).
double principled_smith_ggx(double NoV, double alpha);

// The hooks: pi f_d (N.L) per unit base colour (the diffuse, with subsurface,
// times 1 - metallic), and pi (N.L) (sheen + specular + clear coat), coloured.
ClassicDiffuseFn diffuse_principled;
ClassicSpecularFn specular_principled;

}  // namespace m3055::ref
