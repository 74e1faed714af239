// Burley's principled BRDF in double, term by term as glsl/models/principled.glsl,
// with the same names (docs/models.md#principled-burleys-principled-brdf); the
// formulas and the reasons for their forms are in the GLSL's comments.
#include "reference/principled.h"

#include "numeric/angles.h"
#include "reference/classic.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace m3055::ref {

namespace {
using numeric::kPi;

double mix(double x, double y, double a) { return x * (1.0 - a) + y * a; }
dvec3 mix(const dvec3& x, const dvec3& y, double a) { return x * (1.0 - a) + y * a; }
}  // namespace

double principled_schlick_weight(double u) {
    const double m = std::clamp(1.0 - u, 0.0, 1.0);
    const double m2 = m * m;
    return m2 * m2 * m;
}

dvec3 principled_tint(const dvec3& base_color) {
    const double lum = 0.3 * base_color.r + 0.6 * base_color.g + 0.1 * base_color.b;
    return lum > 0.0 ? base_color / lum : dvec3(1.0);
}

double principled_diffuse_fresnel(double roughness, double LoH2, double FL, double FV) {
    const double fd90 = 0.5 + 2.0 * LoH2 * roughness;
    return mix(1.0, fd90, FL) * mix(1.0, fd90, FV);
}

double principled_subsurface(double roughness, double LoH2, double FL, double FV, double NoL, double NoV) {
    const double fss90 = LoH2 * roughness;
    const double fss = mix(1.0, fss90, FL) * mix(1.0, fss90, FV);
    return 1.25 * (fss * (NoL / (NoL + NoV) - 0.5 * NoL) + 0.5 * NoL);
}

double principled_gtr2_aniso(double HoT, double HoB, double NoH, double ax, double ay) {
    const double x = HoT / ax, y = HoB / ay;
    const double t = x * x + y * y + NoH * NoH;
    return 1.0 / (kPi * ax * ay * t * t);
}

double principled_gtr1(double sin2_h, double cos2_h, double alpha) {
    const double a2 = alpha * alpha;
    return (a2 - 1.0) / (kPi * std::log(a2) * (sin2_h + a2 * cos2_h));
}

double principled_smith_ggx_aniso(double NoV, double VoT, double VoB, double ax, double ay) {
    const double x = VoT * ax, y = VoB * ay;
    return 1.0 / (NoV + std::sqrt(x * x + y * y + NoV * NoV));
}

double principled_smith_ggx(double NoV, double alpha) {
    const double a2 = alpha * alpha;
    const double b = NoV * NoV;
    return 1.0 / (NoV + std::sqrt(a2 + b - a2 * b));
}

// ---- The hooks ---------------------------------------------------------------------

double diffuse_principled(const Material& material, double NoL, double NoV, double LoV) {
    if (!(NoL > 0.0)) return 0.0;
    NoV = std::max(NoV, 0.0);
    const double roughness = material.number("roughness");
    const double LoH2 = std::clamp(0.5 + 0.5 * LoV, 0.0, 1.0);  // cos^2(theta_d) for unit L, V
    const double FL = principled_schlick_weight(NoL), FV = principled_schlick_weight(NoV);
    const double fd = principled_diffuse_fresnel(roughness, LoH2, FL, FV) * NoL;
    const double ss = principled_subsurface(roughness, LoH2, FL, FV, NoL, NoV);
    return (1.0 - material.number("metallic")) * mix(fd, ss, material.number("subsurface"));
}

dvec3 specular_principled(const Material& material, const dvec3& N, const dvec3& L, const dvec3& V, double NoL,
                          double NoV) {
    if (!(NoL > 0.0)) return dvec3(0.0);
    NoV = std::max(NoV, 0.0);
    const TangentFrame frame = tangent_frame(material.vec3("axis"), N);
    const dvec3 sum = L + V;
    const double LoH = 0.5 * glm::length(sum);  // for unit L, V, free of cancellation
    const dvec3 H = glm::dot(sum, sum) > 0.0 ? glm::normalize(sum) : N;  // L = -V: no half vector
    const double NoH = glm::dot(N, H);
    const dvec3 NxH = glm::cross(N, H);
    const double FH = principled_schlick_weight(LoH);

    const dvec3 base = material.vec3("base_color");
    const double metallic = material.number("metallic");
    const dvec3 tint = principled_tint(base);
    const dvec3 sheen =
        (1.0 - metallic) * FH * material.number("sheen") * mix(dvec3(1.0), tint, material.number("sheen_tint"));

    const double aspect = std::sqrt(1.0 - 0.9 * material.number("anisotropic"));
    const double roughness = material.number("roughness");
    const double r2 = roughness * roughness;
    const double ax = std::max(0.001, r2 / aspect), ay = std::max(0.001, r2 * aspect);
    const double Ds = principled_gtr2_aniso(glm::dot(H, frame.T), glm::dot(H, frame.B), NoH, ax, ay);
    const double Gs = principled_smith_ggx_aniso(NoL, glm::dot(L, frame.T), glm::dot(L, frame.B), ax, ay) *
                      principled_smith_ggx_aniso(NoV, glm::dot(V, frame.T), glm::dot(V, frame.B), ax, ay);
    const dvec3 spec0 =
        mix(material.number("specular") * 0.08 * mix(dvec3(1.0), tint, material.number("specular_tint")), base,
            metallic);
    const dvec3 specular = Ds * Gs * mix(spec0, dvec3(1.0), FH);

    const double Dr =
        principled_gtr1(glm::dot(NxH, NxH), NoH * NoH, mix(0.1, 0.001, material.number("clearcoat_gloss")));
    const double Gr = principled_smith_ggx(NoL, 0.25) * principled_smith_ggx(NoV, 0.25);
    const double coat = 0.25 * material.number("clearcoat") * Dr * Gr * mix(0.04, 1.0, FH);

    return (kPi * NoL) * (sheen + specular + dvec3(coat));
}

}  // namespace m3055::ref
