// Diffuse terms of the classic models (docs/spec.md#5-classic-models): the factor of K_diff (x) L_diff
// in the lecture's form, where Lambert is I_diff = (N.L)+ K_diff (x) L_diff.
// C++ twins: reference/classic_terms.cpp (same names).
#include "common/constants.glsl"

// Lambert's cosine law (lecture, seed 003): (N.L)+.
float lambert(float NoL) {
    return max(NoL, 0.0);
}

// Valve's Half-Lambert (Mitchell 2008, seed 004): ((N.L) 0.5 + 0.5)^2; the
// back of the object still gets light, down to 0 at N.L = -1.
float half_lambert(float NoL) {
    float x = NoL * 0.5 + 0.5;
    return x * x;
}

// seed 004's code clamps N.L at 0 first: a constant 1/4 on the unlit side.
float half_lambert_clamped(float NoL) {
    return half_lambert(max(NoL, 0.0));
}

// seed 004's normalized Half-Lambert: x 3/(4 pi), which integrates to 1 over
// the whole sphere of directions (integral of ((x + 1)/2)^2 over it is 4 pi / 3).
float half_lambert_normalized(float NoL) {
    return 3.0 / (4.0 * PI) * half_lambert(NoL);
}

// Oren & Nayar 1994, qualitative model (seed 003), times N.L:
//   (N.L)+ (A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta)),
//   alpha = max(theta_i, theta_o), beta = min(theta_i, theta_o),
//   A = 1 - 0.5 s^2 / (s^2 + 0.33), B = 0.45 s^2 / (s^2 + 0.09).
// With s = L.V - N.L N.V = cos(phi) sin(theta_i) sin(theta_o), the B term is
// max(s, 0) / max(N.L, N.V): no trigonometry, finite everywhere. (The lecture
// prints sin(min) tan(max): swapped; that grows without bound at grazing view.)
float oren_nayar(float sigma, float NoL, float NoV, float LoV) {
    if (NoL <= 0.0) return 0.0;
    NoV = max(NoV, 0.0);
    float s2 = sigma * sigma;
    float A = 1.0 - 0.5 * s2 / (s2 + 0.33);
    float B = 0.45 * s2 / (s2 + 0.09);
    float s = LoV - NoL * NoV;
    return NoL * (A + B * max(s, 0.0) / max(NoL, NoV));
}
