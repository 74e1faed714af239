// Microfacet normal distributions D(h) for the classic `microfacet` model
// (docs/spec.md#5-classic-models; lecture seed 003, seed 002), each normalized so that the integral
// of D(h) (N.h) over the hemisphere is 1. one_minus_NoH = 1 - N.H from
// one_minus_cos (common/math.glsl): narrow lobes need it accurate.
// C++ twins: reference/classic_terms.cpp.
#include "common/constants.glsl"
#include "terms/beckmann.glsl"

// Normalized Blinn-Phong (lecture): (n + 2) / (2 pi) (N.H)^n.
float blinn_phong_D(float n, float NoH, float one_minus_NoH) {
    return (n + 2.0) / (2.0 * PI) * pow_cos(NoH, one_minus_NoH, n);
}

// Torrance-Sparrow's Gaussian (lecture, seed 002): b exp(-(theta_h / m)^2).
// b normalizes it; it depends on m only and has no closed form, so the CPU
// computes it once per lobe in double (ref::gaussian_norm) and the material
// record carries it. theta_h from atan(|N x H|, N.H), accurate near 0.
float gaussian_D(float m, float b, float theta_h) {
    float x = theta_h / m;
    return b * exp(-x * x);
}

// Beckmann (Cook & Torrance 1982): the paper's delta(m, alpha) (terms/beckmann.glsl)
// is exp(-tan^2 a / m^2) / (m^2 cos^4 a) without the 1/pi that normalizes it.
float beckmann_normalized_D(float m, float NoH, float one_minus_NoH) {
    return beckmann_D(m, NoH, one_minus_NoH) / PI;
}

// GGX / Trowbridge-Reitz (Walter et al. 2007): a^2 / (pi ((N.H)^2 (a^2 - 1) + 1)^2),
// the bracket written as sin^2 + a^2 cos^2 with sin^2 = delta (2 - delta):
// 1 - cos^2 in float would lose everything for a = 0.001.
float ggx_D(float alpha, float NoH, float one_minus_NoH) {
    if (NoH <= 0.0) return 0.0;
    float a2 = alpha * alpha;
    float denom = one_minus_NoH * (2.0 - one_minus_NoH) + a2 * NoH * NoH;
    return a2 / (PI * denom * denom);
}

// DISTRIBUTION_*: the choices of the microfacet model's "distribution"
// (generated from the model table: generated/material.glsl).
// D of one lobe: m the roughness (or exponent n for blinn_phong), b the
// Gaussian's normalization.
float microfacet_D(int distribution, float m, float b, float NoH, float one_minus_NoH, float theta_h) {
    if (NoH <= 0.0) return 0.0;
    if (distribution == DISTRIBUTION_BLINN_PHONG) return blinn_phong_D(m, NoH, one_minus_NoH);
    if (distribution == DISTRIBUTION_GAUSSIAN) return gaussian_D(m, b, theta_h);
    if (distribution == DISTRIBUTION_BECKMANN) return beckmann_normalized_D(m, NoH, one_minus_NoH);
    return ggx_D(m, NoH, one_minus_NoH);
}
