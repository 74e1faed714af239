// The paper's reflection models (docs/spec.md#4-paper-models) and the dispatch by family, built
// from the terms in terms.cpp; the C++ twin of glsl/models/highlight.glsl,
// translucent.glsl, metal.glsl and shade.glsl, with the same names. Every
// light l enters through its direction L_l and its scale a_l c_l att spot
// (lights.cpp), or as a node of an area light's quadrature (lit_point.h); a
// light with N.L_l <= 0 contributes nothing (docs/spec.md#4-paper-models).
#include "reference/reference.h"
#include "reference/hooks.h"
#include "reference/classic.h"
#include "reference/conductor.h"

#include "models/model_spec.h"

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace m3055::ref {

namespace {

// docs/spec.md#3-geometry: R_l = 2 (N.L_l) N - L_l; returns R.V.
double mirror_RoV(const dvec3& L, double NoL, const SurfacePoint& point) {
    const dvec3 R = 2.0 * NoL * point.N - L;
    return glm::dot(R, point.V);
}

// docs/spec.md#3-geometry: H_l = normalize(L_l + V), from L + V, or N where L = -V exactly
// (L + V is non-zero whenever N.L > 0 and N.V >= 0; the fallback only keeps
// degenerate input finite), as glsl/models/metal.glsl's function of this name.
dvec3 half_vector_or_normal(const dvec3& L, const dvec3& V, const dvec3& N) {
    const dvec3 sum = L + V;
    return glm::dot(sum, sum) > 0.0 ? sum : N;
}

dvec3 half_vector(const dvec3& L, const SurfacePoint& point) {
    return glm::normalize(half_vector_or_normal(L, point.V, point.N));
}

// sum_j w_j (c+)^n_j over the lobes light `light` uses on `material`.
double exponent_lobe_sum(const Material& material, const Light& light, double c) {
    double sum = 0.0;
    for (const Lobe& lobe : lobes_for(light, material)) sum += lobe.w * pow_safe(c, lobe.m);
    return sum;
}

// The highlight model's two parts, shared with the translucent model (docs/spec.md#42-translucent):
//   C1   = min([d + (1 - d) sum_l a_l c_l (N.L_l)+] C0, 1)      (eq. 3)
//   keep = prod_l (1 - s_l)                                        (eq. 4, once per light)
struct HighlightParts {
    dvec3 C1;
    dvec3 keep;
};

// What one light leaves of the colour below white, 1 - s_l (eq. 4); for a node
// of an area light, exp(-s), the limit of ever more, ever weaker lights
// (docs/spec.md#75-area-lights-the-sky-and-shadows), in which the clamp never acts.
dvec3 highlight_keep(double w, const LitLight& lit, double RoV, double m) {
    if (!lit.node) return dvec3(1.0) - highlight_strength(w, lit.sample.scale, RoV, m);
    return glm::exp(-w * lit.sample.scale * pow_safe(RoV, m));
}

// A colour spectrum (docs/spec.md#73-spectral-colours): each light's diffuse
// share in its own C0, d in D65's: d C0_D65 + (1 - d) sum_l a_l c_l (N.L) C0_l.
HighlightParts highlight_parts_spectral(const Material& material, const LitLights& lights,
                                        const SurfacePoint& point) {
    const double d = material.number("d"), w = material.number("w"), m = material.number("m");
    dvec3 diffuse(0.0), keep(1.0);
    for (const LitLight& lit : lights) {
        const LightSample& sample = lit.sample;
        const double NoL = glm::dot(point.N, sample.L);
        if (!(NoL > 0.0) || sample.scale == dvec3(0.0)) continue;
        diffuse += sample.scale * NoL * spectral_c0(material, lit.light, 1.0);
        keep *= highlight_keep(w, lit, mirror_RoV(sample.L, NoL, point), m);
    }
    return {glm::min(d * spectral_c0(material, nullptr, 1.0) + (1.0 - d) * diffuse, dvec3(1.0)), keep};
}

HighlightParts highlight_parts(const Material& material, const LitLights& lights, const SurfacePoint& point) {
    if (is_spectral(material)) return highlight_parts_spectral(material, lights, point);
    const double d = material.number("d"), w = material.number("w"), m = material.number("m");
    dvec3 diffuse(0.0), keep(1.0);
    for (const LitLight& lit : lights) {
        const LightSample& sample = lit.sample;
        const double NoL = glm::dot(point.N, sample.L);
        if (!(NoL > 0.0)) continue;  // docs/spec.md#4-paper-models: no diffuse, no highlight
        diffuse += sample.scale * NoL;
        keep *= highlight_keep(w, lit, mirror_RoV(sample.L, NoL, point), m);
    }
    return {glm::min((d + (1.0 - d) * diffuse) * material.vec3("color"), dvec3(1.0)), keep};
}

}  // namespace

// ---- highlight (eq. 3-4) and translucent (eq. 5-8) -------------------------------

dvec3 shade_highlight(const Material& material, const LitLights& lights, const SurfacePoint& point) {
    const HighlightParts parts = highlight_parts(material, lights, point);
    return highlight_to_white(parts.C1, parts.keep);
}

// As a premultiplied "over": with keep = prod_l (1 - s_l) and t = Kay's
// opacity, C = 1 - (1 - C1') keep, C1' = (1 - t) C_B + t C1 gives
//   C = [(1 - keep) + keep t C1] + [keep (1 - t)] C_B.
TranslucentShade shade_translucent(const Material& material, const LitLights& lights, const SurfacePoint& point) {
    const HighlightParts parts = highlight_parts(material, lights, point);
    const double t = kay_opacity(material.number("t_n"), material.number("t_p"), glm::dot(point.N, point.V));
    return {(dvec3(1.0) - parts.keep) + parts.keep * t * parts.C1, parts.keep * (1.0 - t)};
}

// ---- metals (eq. 12-16): each model's sum_j w_j lobe_j for one light -------------

// metal (eq. 12-13): sum_j w_j delta(m_j, alpha) G / (N.V), F = C0 (assumption 3).
double beckmann_lobe_sum(const Material& material, const Light& light, const SurfacePoint& point,
                         const dvec3& L, double NoL, double NoV) {
    const dvec3 H = half_vector(L, point);
    const double NoH = glm::dot(point.N, H);
    // V.H = |L + V| / 2 for unit L, V: dot(V, H) cancels when L is nearly
    // -V (2% off at |L + V| = 1e-7, past the bound 2 / V.H on G / N.V).
    // L = -V exactly gives 0, hence no lobe.
    const double VoH = 0.5 * glm::length(L + point.V);
    double sum = 0.0;
    for (const Lobe& lobe : lobes_for(light, material)) sum += lobe.w * beckmann_D(lobe.m, NoH);
    return sum * ct_G_over_NoV(NoH, NoV, NoL, VoH);
}

// metal_blinn (eq. 15): sum_j w_j ((N.H)+)^n_j.
double blinn_lobe_sum(const Material& material, const Light& light, const SurfacePoint& point, const dvec3& L,
                      double, double) {
    return exponent_lobe_sum(material, light, glm::dot(point.N, half_vector(L, point)));
}

// metal_phong (eq. 16): sum_j w_j ((R.V)+)^n_j.
double phong_lobe_sum(const Material& material, const Light& light, const SurfacePoint& point, const dvec3& L,
                      double NoL, double) {
    return exponent_lobe_sum(material, light, mirror_RoV(L, NoL, point));
}

// The metal family's dispatcher (generated in GLSL from the model table): the model's hook.
double metal_lobe_sum(const Material& material, const Light& light, const SurfacePoint& point, const dvec3& L,
                      double NoL, double NoV) {
    return reference_hooks(material.model()).metal(material, light, point, L, NoL, NoV);
}

// A measured metal (docs/spec.md#72-measured-metals) or a colour spectrum (#73):
// d C0_D65 + sum_l a_l c_l lobes_l C0_l(V.H), each C0 summed per wavelength here
// (reference/conductor.h).
dvec3 shade_conductor(const Material& material, const LitLights& lights, const SurfacePoint& point) {
    const double NoV = std::max(glm::dot(point.N, point.V), 0.0);
    dvec3 sum(0.0);
    for (const LitLight& lit : lights) {
        const LightSample& sample = lit.sample;
        const double NoL = glm::dot(point.N, sample.L);
        if (!(NoL > 0.0)) continue;
        const double lobes = metal_lobe_sum(material, *lit.light, point, sample.L, NoL, NoV);
        if (lobes == 0.0 || sample.scale == dvec3(0.0)) continue;  // nothing to colour
        const double VoH = 0.5 * glm::length(sample.L + point.V);  // as beckmann_lobe_sum
        sum += sample.scale * lobes * spectral_c0(material, lit.light, VoH);
    }
    return material.number("d") * spectral_c0(material, nullptr, 1.0) + sum;
}

// The metal family: C = { d + sum_l a_l c_l lobes_l } C0 over the lights with N.L > 0.
dvec3 shade_metal(const Material& material, const LitLights& lights, const SurfacePoint& point) {
    if (is_spectral(material)) return shade_conductor(material, lights, point);
    const double NoV = std::max(glm::dot(point.N, point.V), 0.0);
    dvec3 sum(0.0);
    for (const LitLight& lit : lights) {
        const LightSample& sample = lit.sample;
        const double NoL = glm::dot(point.N, sample.L);
        if (!(NoL > 0.0)) continue;  // docs/spec.md#4-paper-models: no lobe
        sum += sample.scale * metal_lobe_sum(material, *lit.light, point, sample.L, NoL, NoV);
    }
    return (material.number("d") + sum) * material.vec3("color");
}

// ---- every model -------------------------------------------------------------------

dvec3 shade_opaque_lit(const Material& material, const LitLights& lights, const SurfacePoint& point,
                       const dvec3& global_ambient) {
    const ModelSpec& model = material.model();
    switch (model.family) {
        case Family::classic: return shade_classic(material, lights, point, global_ambient);
        case Family::metal: return shade_metal(material, lights, point);
        case Family::opaque: return reference_hooks(model).opaque(material, lights, point);
        case Family::translucent: return shade_highlight(material, lights, point);  // as if t = 1
        case Family::brdf:  // code from a .brdf file runs on the GPU only (passes/brdf_grid.h):
            // no value, and callers that draw what they get (the explorer's polar plot) skip NaN
            return dvec3(std::numeric_limits<double>::quiet_NaN());
    }
    return dvec3(0.0);
}

}  // namespace m3055::ref
