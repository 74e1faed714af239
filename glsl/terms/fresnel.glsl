// Fresnel terms for the classic `microfacet` model (docs/spec.md#5-classic-models).
// C++ twins: reference/classic_terms.cpp.

// Reflectance at normal incidence from the index of refraction: ((n - 1)/(n + 1))^2.
float schlick_F0(float ior) {
    float r = (ior - 1.0) / (ior + 1.0);
    return r * r;
}

// Schlick 1994: F0 + (1 - F0)(1 - cos)^5, cos = V.H (lecture, seed 003).
float schlick_F(float F0, float VoH) {
    float x = 1.0 - clamp(VoH, 0.0, 1.0);
    float x2 = x * x;
    return F0 + (1.0 - F0) * x2 * x2 * x;
}

// Unpolarized dielectric Fresnel (Cook & Torrance 1982; seed 003's formula,
// whose g = sqrt(n^2 + c^2 + 1) and "- 1" in the last denominator are typos):
//   F = 1/2 (g - c)^2 / (g + c)^2 {1 + [c (g + c) - 1]^2 / [c (g - c) + 1]^2},
//   g = sqrt(n^2 + c^2 - 1), c = V.H.
float dielectric_F(float ior, float VoH) {
    float c = clamp(VoH, 0.0, 1.0);
    float g = sqrt(max(ior * ior + c * c - 1.0, 0.0));
    if (g + c <= 0.0) return 1.0;  // n = 1 at grazing: the limit is total reflection
    float a = (g - c) / (g + c);
    float num = c * (g + c) - 1.0;
    float den = c * (g - c) + 1.0;
    return 0.5 * a * a * (1.0 + (num * num) / (den * den));
}
