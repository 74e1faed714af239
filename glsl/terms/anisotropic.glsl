// Anisotropic terms of the classic models (docs/spec.md#5-classic-models, seed 002): the tangent
// frame of the fibre and brushed models, and Ward's highlight.
// C++ twins: reference/classic_terms.cpp.
#include "common/constants.glsl"

// The tangent frame (docs/models.md): T = normalize(axis x N), the direction of
// the grooves, running around `axis` (brushed on a lathe); B = N x T. Within
// 1e-4 rad of the poles (N = +-axis) T = normalize(e x N), e the coordinate
// axis least aligned with `axis`.
void tangent_frame(vec3 axis, vec3 N, out vec3 T, out vec3 B) {
    T = cross(axis, N);
    if (length(T) < 1e-4) {
        vec3 a = abs(axis);
        vec3 e = (a.x <= a.y && a.x <= a.z) ? vec3(1.0, 0.0, 0.0)
                                            : (a.y <= a.z ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0));
        T = cross(e, N);
    }
    T = normalize(T);
    B = cross(N, T);
}

// Ward 1992 (seed 002) in the lecture's form pi f (N.L):
//   f = exp(-((h.T/ax)^2 + (h.B/ay)^2) / (h.N)^2) / (4 pi ax ay sqrt(N.L N.V)),
// h = L + V unnormalized (the exponent is tan^2(theta_h)(cos^2 phi / ax^2 +
// sin^2 phi / ay^2) for any length of h). Zero unless N.L > 0 and N.V > 0.
float ward_specular(float alpha_x, float alpha_y, float NoL, float NoV, float HoT, float HoB, float HoN) {
    if (NoL <= 0.0 || NoV <= 0.0 || HoN <= 0.0) return 0.0;
    float x = HoT / alpha_x, y = HoB / alpha_y;
    float e = (x * x + y * y) / (HoN * HoN);
    if (e > 80.0) return 0.0;  // below 1e-35 of the peak: skip, no 0 * inf
    // N.V floored at 1e-12: finite at the silhouette (a denormal N.V gave Inf).
    return sqrt(NoL / max(NoV, 1e-12)) * exp(-e) / (4.0 * alpha_x * alpha_y);
}
