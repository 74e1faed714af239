// The empirical specular lobes of the classic models (docs/spec.md#5-classic-models): the factor of
// K_spec (x) L_spec. Powers via pow_cos (common/math.glsl), accurate for
// exponents up to 10000. C++ twins: reference/classic_terms.cpp.

// Phong 1975 (seed 001): ((R.V)+)^shininess, from cos and 1 - cos of R, V.
float phong_lobe(float shininess, float RoV, float one_minus_RoV) {
    return pow_cos(RoV, one_minus_RoV, shininess);
}

// Blinn 1977 (seed 003): ((N.H)+)^shininess, from cos and 1 - cos of N, H.
float blinn_phong_lobe(float shininess, float NoH, float one_minus_NoH) {
    return pow_cos(NoH, one_minus_NoH, shininess);
}
