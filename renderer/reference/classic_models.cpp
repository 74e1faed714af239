// The classic models (SPEC 5) in the lecture's shading equation (seed 003),
// built from classic_terms.cpp. C++ twin of glsl/models/classic.glsl.
#include "reference/classic.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace m3055::ref {

namespace {

constexpr double kPi = 3.14159265358979323846;

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

// D G F / (4 N.L N.V) as pi f N.L = pi sum_j w_j D_j G F / (4 N.V), with G / N.V
// from ct_G_over_NoV (finite at grazing view, as the paper's metal).
double microfacet_specular(const Material& material, const dvec3& N, const dvec3& L, const dvec3& V,
                           double NoL, double NoV) {
    const dvec3 H = half_vector(L, V, N);
    const double NoH = glm::dot(N, H);
    const double VoH = 0.5 * glm::length(L + V);  // = V.H for unit L, V, without cancellation
    const double theta_h = angle_between(N, H);
    double D = 0.0;
    for (const Lobe& lobe : material.lobes) D += lobe.w * microfacet_D(material.distribution, lobe.m, NoH, theta_h);
    if (D == 0.0) return 0.0;
    double F = 1.0;
    if (material.fresnel == Fresnel::schlick) F = schlick_F(schlick_F0(material.ior), VoH);
    if (material.fresnel == Fresnel::dielectric) F = dielectric_F(material.ior, VoH);
    return kPi * D * ct_G_over_NoV(NoH, NoV, NoL, VoH) * F / 4.0;
}

}  // namespace

double classic_diffuse(const Material& material, double NoL, double NoV, double LoV) {
    switch (material.model) {
        case Model::lambert: return lambert(NoL);
        case Model::half_lambert: return half_lambert(NoL);
        case Model::half_lambert_clamped: return half_lambert_clamped(NoL);
        case Model::half_lambert_normalized: return half_lambert_normalized(NoL);
        case Model::oren_nayar: return oren_nayar(material.sigma, NoL, NoV, LoV);
        default: return has_specular(material.model) ? lambert(NoL) : 0.0;
    }
}

dvec3 classic_specular(const Material& material, const dvec3& N, const dvec3& L, const dvec3& V) {
    const double NoL = glm::dot(N, L);
    if (!has_specular(material.model) || !(NoL > 0.0)) return dvec3(0.0);
    const double NoV = std::max(glm::dot(N, V), 0.0);
    double lobe = 0.0;
    switch (material.model) {
        case Model::phong: lobe = phong_lobe(material.shininess, glm::dot(2.0 * NoL * N - L, V)); break;
        case Model::blinn_phong: lobe = blinn_phong_lobe(material.shininess, glm::dot(N, half_vector(L, V, N))); break;
        case Model::microfacet: lobe = microfacet_specular(material, N, L, V, NoL, NoV); break;
        case Model::ward: {
            const TangentFrame frame = tangent_frame(material.axis, N);
            const dvec3 h = L + V;
            lobe = ward_specular(material.alpha_x, material.alpha_y, NoL, NoV, glm::dot(h, frame.T),
                                 glm::dot(h, frame.B), glm::dot(h, N));
            break;
        }
        case Model::heidrich_seidel: {
            const TangentFrame frame = tangent_frame(material.axis, N);
            lobe = heidrich_seidel_lobe(material.shininess, angle_between(L, frame.T), angle_between(V, frame.T));
            break;
        }
        default: break;
    }
    return lobe * material.ks;
}

dvec3 classic_brdf(const Material& material, const dvec3& N, const dvec3& L, const dvec3& V) {
    const double NoL = glm::dot(N, L);
    if (!(NoL > 0.0)) return dvec3(0.0);
    const double diffuse = classic_diffuse(material, NoL, glm::dot(N, V), glm::dot(L, V));
    return (diffuse * material.kd + classic_specular(material, N, L, V)) / (kPi * NoL);
}

dvec3 shade_classic(const Material& material, const std::vector<Light>& lights, const SurfacePoint& point,
                    const dvec3& global_ambient) {
    dvec3 I = global_ambient * material.ka + material.emission;
    const double NoV = glm::dot(point.N, point.V);
    for (const Light& light : lights) {
        if (!light.enabled) continue;
        const LightSample sample = sample_light(light, point.P);
        // I_amb,k = C_spot,k a_k ambient_k (x) K_amb: spot-shaped, not attenuated (lecture).
        I += sample.spot * light.intensity * light.ambient * material.ka;
        const double NoL = glm::dot(point.N, sample.L);
        const double diffuse = classic_diffuse(material, NoL, NoV, glm::dot(sample.L, point.V));
        // sample.scale = a_k c_k att_k C_spot,k
        I += sample.scale * (diffuse * material.kd + classic_specular(material, point.N, sample.L, point.V));
    }
    return I;
}

}  // namespace m3055::ref
