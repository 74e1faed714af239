// The classic models' scalar terms (docs/spec.md#5-classic-models), one function per term; each
// mirrors the GLSL function of the same name in glsl/terms/.
#include "reference/classic.h"

#include "numeric/angles.h"
#include "numeric/normalization.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace m3055::ref {

namespace {
using numeric::kPi;
}

// ---- Diffuse -------------------------------------------------------------------

double lambert(double NoL) { return std::max(NoL, 0.0); }

double half_lambert(double NoL) {
    const double x = NoL * 0.5 + 0.5;
    return x * x;
}

double half_lambert_clamped(double NoL) { return half_lambert(std::max(NoL, 0.0)); }

double half_lambert_normalized(double NoL) { return 3.0 / (4.0 * kPi) * half_lambert(NoL); }

double oren_nayar(double sigma, double NoL, double NoV, double LoV) {
    if (!(NoL > 0.0)) return 0.0;
    NoV = std::max(NoV, 0.0);
    const double s2 = sigma * sigma;
    const double A = 1.0 - 0.5 * s2 / (s2 + 0.33);
    const double B = 0.45 * s2 / (s2 + 0.09);
    const double s = LoV - NoL * NoV;  // cos(phi_i - phi_o) sin(theta_i) sin(theta_o)
    const double t = std::max(NoL, NoV);  // cos(beta), beta = min(theta_i, theta_o)
    return NoL * (A + B * std::max(s, 0.0) / t);
}

// ---- Empirical lobes ---------------------------------------------------------------

double phong_lobe(double shininess, double RoV) { return pow_safe(RoV, shininess); }

double blinn_phong_lobe(double shininess, double NoH) { return pow_safe(NoH, shininess); }


// ---- Distributions -------------------------------------------------------------------

double blinn_phong_D(double n, double NoH) { return (n + 2.0) / (2.0 * kPi) * pow_safe(NoH, n); }

double gaussian_D(double m, double b, double theta_h) {
    const double x = theta_h / m;
    return b * std::exp(-x * x);
}

double beckmann_normalized_D(double m, double NoH) { return beckmann_D(m, NoH) / kPi; }

double ggx_D(double alpha, double NoH) {
    if (!(NoH > 0.0)) return 0.0;
    const double c2 = std::min(NoH * NoH, 1.0);
    const double a2 = alpha * alpha;
    const double denom = (1.0 - c2) + a2 * c2;  // (N.H)^2 (a^2 - 1) + 1
    return a2 / (kPi * denom * denom);
}

double microfacet_D(Distribution distribution, double m, double NoH, double theta_h) {
    if (!(NoH > 0.0)) return 0.0;
    switch (distribution) {
        case Distribution::blinn_phong: return blinn_phong_D(m, NoH);
        case Distribution::gaussian: {
            // b depends on m only: remember the last few (a material has <= 4 lobes).
            thread_local double cached_m[4] = {-1, -1, -1, -1}, cached_b[4];
            thread_local int next = 0;
            for (int i = 0; i < 4; ++i)
                if (cached_m[i] == m) return gaussian_D(m, cached_b[i], theta_h);
            const double b = numeric::gaussian_norm(m);
            cached_m[next] = m, cached_b[next] = b, next = (next + 1) % 4;
            return gaussian_D(m, b, theta_h);
        }
        case Distribution::beckmann: return beckmann_normalized_D(m, NoH);
        case Distribution::ggx: return ggx_D(m, NoH);
    }
    return 0.0;
}

// ---- Fresnel ---------------------------------------------------------------------------

double schlick_F0(double ior) {
    const double r = (ior - 1.0) / (ior + 1.0);
    return r * r;
}

double schlick_F(double F0, double VoH) {
    const double x = 1.0 - std::clamp(VoH, 0.0, 1.0);
    const double x2 = x * x;
    return F0 + (1.0 - F0) * x2 * x2 * x;
}

double dielectric_F(double ior, double VoH) {
    const double c = std::clamp(VoH, 0.0, 1.0);
    const double g = std::sqrt(std::max(ior * ior + c * c - 1.0, 0.0));
    if (!(g + c > 0.0)) return 1.0;  // n = 1 at grazing: the limit is total reflection
    const double a = (g - c) / (g + c);
    const double num = c * (g + c) - 1.0;
    const double den = c * (g - c) + 1.0;
    return 0.5 * a * a * (1.0 + (num * num) / (den * den));
}

// ---- Anisotropic ------------------------------------------------------------------------

TangentFrame tangent_frame(const dvec3& axis, const dvec3& N) {
    dvec3 T = glm::cross(axis, N);
    if (glm::length(T) < 1e-4) {
        const dvec3 a = glm::abs(axis);
        const dvec3 e = a.x <= a.y && a.x <= a.z ? dvec3(1, 0, 0) : a.y <= a.z ? dvec3(0, 1, 0) : dvec3(0, 0, 1);
        T = glm::cross(e, N);
    }
    TangentFrame frame;
    frame.T = glm::normalize(T);
    frame.B = glm::cross(N, frame.T);
    return frame;
}

double ward_specular(double alpha_x, double alpha_y, double NoL, double NoV, double HoT, double HoB,
                     double HoN) {
    if (!(NoL > 0.0) || !(NoV > 0.0) || !(HoN > 0.0)) return 0.0;
    const double x = HoT / alpha_x, y = HoB / alpha_y;
    const double exponent = (x * x + y * y) / (HoN * HoN);
    if (exponent > 700.0) return 0.0;
    // N.V floored at 1e-12 as in the GLSL: finite at the silhouette.
    return std::sqrt(NoL / std::max(NoV, 1e-12)) * std::exp(-exponent) / (4.0 * alpha_x * alpha_y);
}

}  // namespace m3055::ref
