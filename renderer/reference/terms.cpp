// The scalar terms of the paper's models (docs/spec.md#4-paper-models), one function per term.
// Each mirrors the GLSL function of the same name in glsl/terms/.
#include "reference/reference.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace m3055::ref {

// docs/spec.md#4-paper-models: x^e with x^0 = 1 for every x >= 0 (std::pow(0, 0) is 1 too, but the
// GLSL pow(0, 0) is undefined, so both sides spell the rule out).
double pow_safe(double x, double e) {
    x = std::max(x, 0.0);
    if (e == 0.0) return 1.0;
    if (x == 0.0) return 0.0;
    return std::pow(x, e);
}

// eq. 13/17: delta(m, a) = exp(-tan^2 a / m^2) / (m^2 cos^4 a), cos a = NoH.
// tan^2 is taken as (1 - c^2) / c^2 (no trig), and the lobe is 0 once the
// exponent is so large that exp underflows: the true value is then below
// 1e-300, and this avoids 0 * inf when NoH -> 0.
double beckmann_D(double m, double NoH) {
    if (!(NoH > 0.0)) return 0.0;
    const double c2 = std::min(NoH * NoH, 1.0);
    const double m2 = m * m;
    const double exponent = (1.0 - c2) / (c2 * m2);
    if (exponent > 700.0) return 0.0;
    return std::exp(-exponent) / (m2 * c2 * c2);
}

// eq. 12: Cook-Torrance masking/shadowing G = min{1, 2 NoH NoV / VoH, 2 NoH NoL / VoH}.
double ct_G(double NoH, double NoV, double NoL, double VoH) {
    if (!(VoH > 0.0)) return 0.0;
    const double g_view = 2.0 * NoH * NoV / VoH;
    const double g_light = 2.0 * NoH * NoL / VoH;
    return std::max(0.0, std::min({1.0, g_view, g_light}));
}

// eq. 12's G / NoV, rearranged as min(2 NoH / VoH, min(1, 2 NoH NoL / VoH) / NoV):
// algebraically equal for NoV > 0 and finite at NoV = 0 (grazing view, the
// silhouette), where it tends to 2 NoH / VoH.
double ct_G_over_NoV(double NoH, double NoV, double NoL, double VoH) {
    if (!(VoH > 0.0)) return 0.0;
    const double view_term = std::max(0.0, 2.0 * NoH / VoH);               // (2 NoH NoV / VoH) / NoV
    const double rest = std::max(0.0, std::min(1.0, 2.0 * NoH * NoL / VoH));  // min(1, light term)
    // min(view_term, rest / NoV) without dividing by a zero NoV.
    if (rest >= view_term * NoV) return view_term;
    return rest / NoV;
}

// eq. 6: Kay's opacity t = t_n ((1 - cos b)+)^t_p, cos b = (N.V)+.
double kay_opacity(double t_n, double t_p, double NoV) {
    const double cos_b = std::max(NoV, 0.0);
    return t_n * pow_safe(1.0 - cos_b, t_p);
}

// eq. 4, one light's share of white: s_l = clamp(w a_l c_l ((R.V)+)^m, 0, 1).
dvec3 highlight_strength(double w, const dvec3& scale, double RoV, double m) {
    return glm::clamp(w * pow_safe(RoV, m) * scale, dvec3(0.0), dvec3(1.0));
}

// eq. 4 once per light: C = 1 - (1 - C1) prod_l (1 - s_l), independent of the lights' order.
dvec3 highlight_to_white(const dvec3& C1, const dvec3& keep) { return dvec3(1.0) - (dvec3(1.0) - C1) * keep; }

}  // namespace m3055::ref
