// What each light delivers at a surface point (docs/spec.md#3-geometry and #5-classic-models): direction
// towards the light and the colour scale a_l c_l att_l C_spot,l.
#include "reference/reference.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace m3055::ref {

// docs/spec.md#5-classic-models: distance attenuation 1 / (S_c + S_l r + S_q r^2); the floor keeps an
// all-zero set of coefficients finite.
static double distance_attenuation(const Light& light, double r) {
    const double denom = light.att_constant + light.att_linear * r + light.att_quadratic * r * r;
    return 1.0 / std::max(denom, 1e-6);
}

// docs/spec.md#5-classic-models: C_spot = ((-L . L_dir)+)^L_exp, L_dir the direction the spot shines along.
static double spot_factor(const Light& light, const dvec3& L) {
    return pow_safe(-glm::dot(L, light.spot_direction), light.spot_exponent);
}

LightSample sample_light(const Light& light, const dvec3& P) {
    LightSample sample;
    sample.scale = dvec3(0.0);
    sample.L = dvec3(0.0);
    if (light.type != LightType::directional && light.type != LightType::point && light.type != LightType::spot)
        throw std::logic_error(std::string(to_string(light.type)) +
                               " lights have no one direction: the reference integrates them (reference/lit_point.h)");

    if (light.type == LightType::directional) {
        sample.L = light.direction;  // unit, from the surface towards the light
        if (light.enabled) sample.scale = light.intensity * light.color;
        return sample;
    }

    const dvec3 to_light = light.position - P;
    const double r = glm::length(to_light);
    // C_spot alone (the classic models' per-light ambient); with L = 0 where
    // r = 0, as the GLSL light_sample computes it.
    if (light.type == LightType::spot) sample.spot = spot_factor(light, r > 0.0 ? to_light / r : dvec3(0.0));
    // A light exactly at P has no direction: L stays 0, so N.L = 0 and the
    // light contributes nothing (no NaN).
    if (!(r > 0.0)) return sample;
    sample.L = to_light / r;
    if (!light.enabled) return sample;

    double factor = distance_attenuation(light, r);
    if (light.type == LightType::spot) factor *= sample.spot;
    sample.scale = light.intensity * factor * light.color;
    return sample;
}

LitLights sampled_lights(const std::vector<Light>& lights, const dvec3& P) {
    LitLights lit;
    lit.reserve(lights.size());
    for (const Light& light : lights) lit.push_back({&light, sample_light(light, P), false});
    return lit;
}

}  // namespace m3055::ref
