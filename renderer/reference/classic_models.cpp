// The classic models (docs/spec.md#5-classic-models) in the lecture's shading equation (seed 003),
// built from classic_terms.cpp: each model's hook NAME_reflect (the colour one
// light reflects per unit light scale) and the family's composer
// shade_classic. C++ twin of glsl/models/classic.glsl, with the same names.
#include "reference/classic.h"
#include "reference/conductor.h"
#include "reference/hooks.h"

#include "models/model_spec.h"
#include "numeric/angles.h"
#include "numeric/normalization.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace m3055::ref {

namespace {

using numeric::kPi;

// H = normalize(L + V); N where L = -V exactly (as the paper's models do).
dvec3 half_vector(const dvec3& L, const dvec3& V, const dvec3& N) {
    const dvec3 sum = L + V;
    const double len = glm::length(sum);
    return len > 0.0 ? sum / len : N;
}

// The angle between unit vectors, accurate near 0 and pi (atan2, not acos).
double angle_between(const dvec3& a, const dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

}  // namespace

// ---- Diffuse hooks: the factor of K_diff (x) L_diff ------------------------------------

double diffuse_lambert(const Material&, double NoL, double, double) { return lambert(NoL); }
double diffuse_half_lambert(const Material&, double NoL, double, double) { return half_lambert(NoL); }
double diffuse_half_lambert_clamped(const Material&, double NoL, double, double) { return half_lambert_clamped(NoL); }

double diffuse_half_lambert_normalized(const Material&, double NoL, double, double) {
    return half_lambert_normalized(NoL);
}

double diffuse_oren_nayar(const Material& material, double NoL, double NoV, double LoV) {
    return oren_nayar(material.number("sigma"), NoL, NoV, LoV);
}

// Minnaert 1941: (k + 1)/2 (N.L)^k (N.V)^(k - 1), N.V floored at 1e-4 as in the GLSL.
double diffuse_minnaert(const Material& material, double NoL, double NoV, double) {
    if (!(NoL > 0.0)) return 0.0;
    const double k = material.number("minnaert_k");
    return 0.5 * (k + 1.0) * std::pow(NoL, k) * std::pow(std::max(NoV, 1e-4), k - 1.0);
}

// ---- Specular hooks: I_spec / L_spec, K_spec included, 0 where N.L <= 0 --------------------

dvec3 specular_phong(const Material& material, const dvec3& N, const dvec3& L, const dvec3& V, double NoL,
                     double) {
    if (!(NoL > 0.0)) return dvec3(0.0);
    return phong_lobe(material.number("shininess"), glm::dot(2.0 * NoL * N - L, V)) * material.vec3("ks");
}

dvec3 specular_blinn_phong(const Material& material, const dvec3& N, const dvec3& L, const dvec3& V, double NoL,
                           double) {
    if (!(NoL > 0.0)) return dvec3(0.0);
    return blinn_phong_lobe(material.number("shininess"), glm::dot(N, half_vector(L, V, N))) * material.vec3("ks");
}

// D G F / (4 N.L N.V) as pi f N.L = pi sum_j w_j D_j G F / (4 N.V), with G / N.V
// from ct_G_over_NoV (finite at grazing view, as the paper's metal).
double microfacet_lobe(const Material& material, const dvec3& N, const dvec3& L, const dvec3& V, double NoL,
                       double NoV) {
    const dvec3 H = half_vector(L, V, N);
    const double NoH = glm::dot(N, H);
    const double VoH = 0.5 * glm::length(L + V);  // = V.H for unit L, V, without cancellation
    const double theta_h = angle_between(N, H);
    const auto distribution = static_cast<Distribution>(material.choice("distribution"));
    double D = 0.0;
    for (const Lobe& lobe : material.lobes()) D += lobe.w * microfacet_D(distribution, lobe.m, NoH, theta_h);
    if (D == 0.0) return 0.0;
    const auto fresnel = static_cast<Fresnel>(material.choice("fresnel"));
    const double ior = material.number("ior");
    double F = 1.0;
    if (fresnel == Fresnel::schlick) F = schlick_F(schlick_F0(ior), VoH);
    if (fresnel == Fresnel::dielectric) F = dielectric_F(ior, VoH);
    return kPi * D * ct_G_over_NoV(NoH, NoV, NoL, VoH) * F / 4.0;
}

dvec3 specular_microfacet(const Material& material, const dvec3& N, const dvec3& L, const dvec3& V, double NoL,
                          double NoV) {
    if (!(NoL > 0.0)) return dvec3(0.0);
    return microfacet_lobe(material, N, L, V, NoL, std::max(NoV, 0.0)) * material.vec3("ks");
}

dvec3 specular_ward(const Material& material, const dvec3& N, const dvec3& L, const dvec3& V, double NoL,
                    double NoV) {
    if (!(NoL > 0.0)) return dvec3(0.0);
    const TangentFrame frame = tangent_frame(material.vec3("axis"), N);
    const dvec3 h = L + V;
    return ward_specular(material.number("alpha_x"), material.number("alpha_y"), NoL, std::max(NoV, 0.0),
                         glm::dot(h, frame.T), glm::dot(h, frame.B), glm::dot(h, N)) *
           material.vec3("ks");
}

// Heidrich & Seidel 1998 (seed 002): ((sin(L,T) sin(V,T) - cos(L,T) cos(V,T))+)^n
// = (cos x)^n with x = pi - angle(L,T) - angle(V,T), from the two angles.
double heidrich_seidel_lobe(double n, double angle_LT, double angle_VT) {
    return pow_safe(std::cos(kPi - angle_LT - angle_VT), n);
}

dvec3 specular_heidrich_seidel(const Material& material, const dvec3& N, const dvec3& L, const dvec3& V,
                               double NoL, double) {
    if (!(NoL > 0.0)) return dvec3(0.0);
    const TangentFrame frame = tangent_frame(material.vec3("axis"), N);
    return heidrich_seidel_lobe(material.number("shininess"), angle_between(L, frame.T), angle_between(V, frame.T)) *
           material.vec3("ks");
}

// ---- The family and its views ---------------------------------------------------------------

// K_diff, the colour the diffuse hook's factor multiplies: kd, or for a model
// whose diffuse colour has a name of its own, its derived value "kd", which the
// GLSL composer reads as mat.kd (principled: its base_color; models/builtin_models.cpp).
static dvec3 diffuse_colour(const Material& material) {
    if (material.has("kd")) return material.vec3("kd");
    for (const DerivedValue& value : material.model().derived)
        if (value.name == "kd" && value.floats == 3) {
            float kd[3];
            value.fill(material, kd);
            return dvec3(kd[0], kd[1], kd[2]);
        }
    throw std::logic_error("classic model " + material.model_name() + " has no kd");
}

// I_diff + I_spec for unit light scale: the two hooks of the material's model.
static dvec3 classic_reflect(const Material& material, const dvec3& N, const dvec3& L, const dvec3& V, double NoL,
                             double NoV) {
    const ReferenceHooks& hooks = reference_hooks(material.model());
    const double diffuse = hooks.classic_diffuse(material, NoL, NoV, glm::dot(L, V));
    dvec3 I = diffuse * diffuse_colour(material);
    if (hooks.classic_specular) I += hooks.classic_specular(material, N, L, V, NoL, NoV);
    return I;
}

dvec3 classic_specular(const Material& material, const dvec3& N, const dvec3& L, const dvec3& V) {
    ClassicSpecularFn* specular = reference_hooks(material.model()).classic_specular;
    return specular ? specular(material, N, L, V, glm::dot(N, L), glm::dot(N, V)) : dvec3(0.0);
}

dvec3 classic_brdf(const Material& material, const dvec3& N, const dvec3& L, const dvec3& V) {
    const double NoL = glm::dot(N, L);
    if (!(NoL > 0.0)) return dvec3(0.0);
    return classic_reflect(material, N, L, V, NoL, glm::dot(N, V)) / (kPi * NoL);
}

// A classic material whose colours are spectral (glsl/models/classic.glsl
// shade_classic_spectral): a microfacet conductor (docs/spec.md#72-measured-metals),
// K_spec F the metal's C0 for each light at V.H, and/or a kd_spectrum
// (#73-spectral-colours), K_diff its colour under each light; summed per wavelength.
dvec3 shade_classic_spectral(const Material& material, const LitLights& lights, const SurfacePoint& point,
                             const dvec3& global_ambient) {
    const bool metal = is_conductor(material);
    const ReflectanceSpectrum* kd_spectrum = material.colour_spectrum();
    Material white = material;  // a conductor: K_spec = 1 and F = 1, the C0 carries both
    if (metal) {
        white.set_vec3("ks", dvec3(1.0));
        white.set_choice("fresnel", "none");
    }
    const ReferenceHooks& hooks = reference_hooks(material.model());
    const dvec3 ka = material.vec3("ka");
    dvec3 I = global_ambient * ka + material.vec3("emission");
    const double NoV = glm::dot(point.N, point.V);
    for (const LitLight& lit : lights) {
        const Light& light = *lit.light;
        if (!light.enabled) continue;
        const LightSample& sample = lit.sample;
        if (!lit.node) I += sample.spot * light.intensity * light.ambient * ka;
        if (sample.scale == dvec3(0.0)) continue;
        const double NoL = glm::dot(point.N, sample.L);
        const double diffuse = hooks.classic_diffuse(material, NoL, NoV, glm::dot(sample.L, point.V));
        const dvec3 c0 = metal ? conductor_c0(material, &light, 0.5 * glm::length(sample.L + point.V)) : dvec3(1.0);
        const dvec3 kd = kd_spectrum ? spectral_c0(material, &light, 1.0) : material.vec3("kd");  // the spectrum is kd's
        const dvec3 specular =
            hooks.classic_specular ? hooks.classic_specular(white, point.N, sample.L, point.V, NoL, NoV) : dvec3(0.0);
        I += sample.scale * (diffuse * kd + specular * c0);
    }
    return I;
}

// The lecture's equation over the lights (glsl/models/classic.glsl shade_classic).
dvec3 shade_classic(const Material& material, const LitLights& lights, const SurfacePoint& point,
                    const dvec3& global_ambient) {
    if (is_spectral(material)) return shade_classic_spectral(material, lights, point, global_ambient);
    const dvec3 ka = material.vec3("ka");
    dvec3 I = global_ambient * ka + material.vec3("emission");
    const double NoV = glm::dot(point.N, point.V);
    for (const LitLight& lit : lights) {
        const Light& light = *lit.light;
        if (!light.enabled) continue;
        const LightSample& sample = lit.sample;
        // I_amb,k = C_spot,k a_k ambient_k (x) K_amb: spot-shaped, not attenuated (lecture).
        if (!lit.node) I += sample.spot * light.intensity * light.ambient * ka;
        const double NoL = glm::dot(point.N, sample.L);
        // sample.scale = a_k c_k att_k C_spot,k
        I += sample.scale * classic_reflect(material, point.N, sample.L, point.V, NoL, NoV);
    }
    return I;
}

}  // namespace m3055::ref
