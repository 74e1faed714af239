// The paper's reflection models (SPEC 4), built from the terms in terms.cpp.
// Every light l enters through its direction L_l and its scale a_l c_l att spot
// (lights.cpp); a light with N.L_l <= 0 contributes nothing at all (SPEC 4).
#include "reference/reference.h"
#include "reference/classic.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>

namespace m3055::ref {

namespace {

// One light as seen from the surface point, kept only where N.L > 0.
struct LitLight {
    dvec3 L;
    dvec3 scale;  // a_l c_l (att_l C_spot,l)
    double NoL;   // > 0
    const Light* light;
};

std::vector<LitLight> lights_facing(const std::vector<Light>& lights, const SurfacePoint& point) {
    std::vector<LitLight> lit;
    for (const Light& light : lights) {
        const LightSample sample = sample_light(light, point.P);
        const double NoL = glm::dot(point.N, sample.L);
        if (!(NoL > 0.0)) continue;  // SPEC 4: no diffuse, no highlight, no lobe
        lit.push_back({sample.L, sample.scale, NoL, &light});
    }
    return lit;
}

// SPEC 3: R_l = 2 (N.L_l) N - L_l; returns R.V.
double mirror_RoV(const LitLight& l, const SurfacePoint& point) {
    const dvec3 R = 2.0 * l.NoL * point.N - l.L;
    return glm::dot(R, point.V);
}

// SPEC 3: H_l = normalize(L_l + V). L + V is non-zero whenever N.L > 0 and
// N.V >= 0; the fallback only keeps degenerate input finite.
dvec3 half_vector(const LitLight& l, const SurfacePoint& point) {
    const dvec3 sum = l.L + point.V;
    const double len = glm::length(sum);
    return len > 0.0 ? sum / len : point.N;
}

// eq. 3 (several lights): D = [d + (1 - d) sum_l a_l c_l (N.L_l)+] C0.
dvec3 diffuse_D(const Material& material, const std::vector<LitLight>& lit) {
    dvec3 sum(0.0);
    for (const LitLight& l : lit) sum += l.scale * l.NoL;
    return (material.d + (1.0 - material.d) * sum) * material.color;
}

// eq. 4, one light's share of white: s_l = clamp(w a_l c_l ((R_l.V)+)^m, 0, 1).
dvec3 highlight_share(const Material& material, const LitLight& l, const SurfacePoint& point) {
    const double lobe = pow_safe(mirror_RoV(l, point), material.m);
    return glm::clamp(material.w * lobe * l.scale, dvec3(0.0), dvec3(1.0));
}

// eq. 4 applied once per light: what is left of the non-white part,
// prod_l (1 - s_l). Independent of the order of the lights.
dvec3 remaining_after_highlights(const Material& material, const std::vector<LitLight>& lit,
                                 const SurfacePoint& point) {
    dvec3 remaining(1.0);
    for (const LitLight& l : lit) remaining *= dvec3(1.0) - highlight_share(material, l, point);
    return remaining;
}

// eq. 3-4 (4.1): C = 1 - (1 - C1) prod_l (1 - s_l), C1 = min(D, 1).
dvec3 shade_highlight(const Material& material, const std::vector<LitLight>& lit,
                      const SurfacePoint& point) {
    const dvec3 C1 = glm::min(diffuse_D(material, lit), dvec3(1.0));
    return dvec3(1.0) - (dvec3(1.0) - C1) * remaining_after_highlights(material, lit, point);
}

// eq. 12-14 (4.3): C = { d + sum_l a_l c_l sum_j w_j delta(m_j, a_l) G_l / (N.V) } C0,
// with Fresnel F = C0 (the paper's assumption 3).
dvec3 shade_metal(const Material& material, const std::vector<LitLight>& lit,
                  const SurfacePoint& point) {
    const double NoV = std::max(glm::dot(point.N, point.V), 0.0);
    dvec3 sum(0.0);
    for (const LitLight& l : lit) {
        const dvec3 H = half_vector(l, point);
        const double NoH = glm::dot(point.N, H);
        // V.H = |L + V| / 2 for unit L, V: dot(V, H) cancels when L is nearly
        // -V (2% off at |L + V| = 1e-7, past the bound 2 / V.H on G / N.V).
        // L = -V exactly gives 0, hence no lobe, as before.
        const double VoH = 0.5 * glm::length(l.L + point.V);
        const double G_over_NoV = ct_G_over_NoV(NoH, NoV, l.NoL, VoH);
        double lobes = 0.0;
        for (const Lobe& lobe : lobes_for(*l.light, material))
            lobes += lobe.w * beckmann_D(lobe.m, NoH);
        sum += l.scale * (lobes * G_over_NoV);
    }
    return (material.d + sum) * material.color;
}

// eq. 15 (4.4): C = { d + sum_l a_l c_l sum_j w_j ((N.H_l)+)^n_j } C0.
dvec3 shade_metal_blinn(const Material& material, const std::vector<LitLight>& lit,
                        const SurfacePoint& point) {
    dvec3 sum(0.0);
    for (const LitLight& l : lit) {
        const double NoH = glm::dot(point.N, half_vector(l, point));
        double lobes = 0.0;
        for (const Lobe& lobe : lobes_for(*l.light, material)) lobes += lobe.w * pow_safe(NoH, lobe.m);
        sum += l.scale * lobes;
    }
    return (material.d + sum) * material.color;
}

// eq. 16 (4.4): C = { d + sum_l a_l c_l sum_j w_j ((R_l.V)+)^n_j } C0.
dvec3 shade_metal_phong(const Material& material, const std::vector<LitLight>& lit,
                        const SurfacePoint& point) {
    dvec3 sum(0.0);
    for (const LitLight& l : lit) {
        const double RoV = mirror_RoV(l, point);
        double lobes = 0.0;
        for (const Lobe& lobe : lobes_for(*l.light, material)) lobes += lobe.w * pow_safe(RoV, lobe.m);
        sum += l.scale * lobes;
    }
    return (material.d + sum) * material.color;
}

}  // namespace

dvec3 shade_opaque(const Material& material, const std::vector<Light>& lights,
                   const SurfacePoint& point, const dvec3& global_ambient) {
    if (is_classic(material.model)) return shade_classic(material, lights, point, global_ambient);
    const std::vector<LitLight> lit = lights_facing(lights, point);
    switch (material.model) {
        case Model::highlight:
        case Model::translucent:  // as if t = 1: exactly the highlight model
            return shade_highlight(material, lit, point);
        case Model::metal: return shade_metal(material, lit, point);
        case Model::metal_blinn: return shade_metal_blinn(material, lit, point);
        case Model::metal_phong: return shade_metal_phong(material, lit, point);
        default: break;  // the classic models returned above
    }
    return dvec3(0.0);
}

// eq. 5-8 (4.2), as a premultiplied "over": with P = prod_l (1 - s_l) and
// t = Kay's opacity, C = 1 - (1 - C1) P, C1 = (1 - t) C_B + t min(D, 1) gives
//   C = [(1 - P) + P t min(D, 1)] + [P (1 - t)] C_B.
TranslucentShade shade_translucent(const Material& material, const std::vector<Light>& lights,
                                   const SurfacePoint& point) {
    const std::vector<LitLight> lit = lights_facing(lights, point);
    const double t = kay_opacity(material.t_n, material.t_p, glm::dot(point.N, point.V));
    const dvec3 P = remaining_after_highlights(material, lit, point);
    const dvec3 D = glm::min(diffuse_D(material, lit), dvec3(1.0));
    TranslucentShade shade;
    shade.color = (dvec3(1.0) - P) + P * t * D;
    shade.transmittance = P * (1.0 - t);
    return shade;
}

}  // namespace m3055::ref
