#include "reference/lit_point.h"

#include "reference/classic.h"
#include "reference/emitters.h"
#include "reference/hooks.h"
#include "reference/scene_bvh.h"

#include "models/model_spec.h"
#include "scene/area_light.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <optional>

namespace m3055::ref {

namespace {

Shade6 as_shade6(const dvec3& colour, const dvec3& transmittance = dvec3(0.0)) {
    return {colour.r, colour.g, colour.b, transmittance.r, transmittance.g, transmittance.b};
}

// A node of `light`: a directional light from the node's direction, scale L c dw.
LitLight node_light(const Light& light, const dvec3& radiance_of_light, const QuadratureNode& node) {
    return {&light, LightSample{node.direction, radiance_of_light * node.solid_angle, 1.0}, true};
}

// A directional, point or spot light at the point: its sample, blocked by the
// occluders when it casts a shadow (only where it lights the point: N.L > 0).
LitLight point_light(const Light& light, const SurfacePoint& point, const LightingOptions& options) {
    LitLight lit{&light, sample_light(light, point.P), false};
    if (!light.shadow || !options.occluders || lit.sample.scale == dvec3(0.0)) return lit;
    if (!(glm::dot(point.N, lit.sample.L) > 0.0)) return lit;
    const double distance = light.type == LightType::directional ? std::numeric_limits<double>::infinity()
                                                                  : glm::length(light.position - point.P);
    if (!options.occluders->sees(point.P, point.N, lit.sample.L, distance)) lit.sample.scale = dvec3(0.0);
    return lit;
}

// The closed form where it applies: a Lambert surface, a rect or the sky, no shadow.
bool closed_form_applies(const Light& light, bool lambertian, const LightingOptions& options) {
    return options.quadrature.closed_forms && lambertian && !(light.shadow && options.occluders) &&
           (light.type == LightType::rect || light.type == LightType::sky);
}

void add_area_light(const Light& light, const SurfacePoint& point, const Composer& compose, bool lambertian,
                    const LightingOptions& options, const Shade6& base, LitLights& lit) {
    const dvec3 L = radiance(light);
    if (closed_form_applies(light, lambertian, options)) {
        // (N.w)+ integrates to the projected solid angle: one node along N carries it whole.
        const double projected = *projected_solid_angle(light, point);
        if (options.stats) ++options.stats->closed;
        if (projected > 0.0) lit.push_back({&light, LightSample{point.N, L * projected, 1.0}, true});
        return;
    }
    const std::vector<Patch> patches = emitter_patches(light, point);
    if (patches.empty()) return;
    AreaIntegrand integrand;
    integrand.value = [&](const std::vector<QuadratureNode>& nodes) {
        LitLights some;
        some.reserve(nodes.size());
        for (const QuadratureNode& node : nodes) some.push_back(node_light(light, L, node));
        Shade6 share = compose(some);
        for (int c = 0; c < 6; ++c) share[c] -= base[c];
        return share;
    };
    if (light.shadow && options.occluders)
        integrand.visible = [&](const QuadratureNode& node) {
            return options.occluders->sees(point.P, point.N, node.direction, node.distance);
        };
    integrand.base = base;
    const double NoV = glm::dot(point.N, point.V);
    if (NoV > 0.0) integrand.peak = glm::normalize(2.0 * NoV * point.N - point.V);  // the mirror direction R
    for (const QuadratureNode& node : integrate_area(patches, integrand, options.quadrature, options.stats))
        lit.push_back(node_light(light, L, node));
}

}  // namespace

bool is_lambertian(const Material& material) {
    if (material.model().family != Family::classic) return false;
    const ReferenceHooks& hooks = reference_hooks(material.model());
    return hooks.classic_diffuse == &diffuse_lambert && hooks.classic_specular == nullptr;
}

bool needs_lit_lights(const std::vector<Light>& lights, const LightingOptions& options) {
    for (const Light& light : lights)
        if (is_area_light(light.type) || (light.shadow && options.occluders)) return true;
    return false;
}

LitLights lit_lights(const std::vector<Light>& lights, const SurfacePoint& point, const Composer& compose,
                     bool lambertian, const LightingOptions& options) {
    LitLights lit;
    for (const Light& light : lights)
        if (!is_area_light(light.type)) lit.push_back(point_light(light, point, options));
    std::optional<Shade6> base;  // what the surface shows with no light: each area light's share is over it
    for (const Light& light : lights) {
        if (!is_area_light(light.type) || !light.enabled || !(light.intensity > 0.0)) continue;
        if (!base) base = compose({});
        add_area_light(light, point, compose, lambertian, options, *base, lit);
    }
    return lit;
}

// ---- every model under every light ---------------------------------------------------

dvec3 shade_opaque(const Material& material, const std::vector<Light>& lights, const SurfacePoint& point,
                   const dvec3& global_ambient, const LightingOptions& options) {
    if (!needs_lit_lights(lights, options))
        return shade_opaque_lit(material, sampled_lights(lights, point.P), point, global_ambient);
    if (material.model().family == Family::brdf)  // no C++ twin: NaN, as shade_opaque_lit gives
        return shade_opaque_lit(material, {}, point, global_ambient);
    const Composer compose = [&](const LitLights& lit) {
        return as_shade6(shade_opaque_lit(material, lit, point, global_ambient));
    };
    return shade_opaque_lit(material, lit_lights(lights, point, compose, is_lambertian(material), options), point,
                            global_ambient);
}

TranslucentShade shade_translucent_model(const Material& material, const std::vector<Light>& lights,
                                         const SurfacePoint& point, const LightingOptions& options) {
    TranslucentShadeFn* hook = reference_hooks(material.model()).translucent;
    if (!needs_lit_lights(lights, options)) return hook(material, sampled_lights(lights, point.P), point);
    const Composer compose = [&](const LitLights& lit) {
        const TranslucentShade shade = hook(material, lit, point);
        return as_shade6(shade.color, shade.transmittance);
    };
    return hook(material, lit_lights(lights, point, compose, false, options), point);
}

// The hooks and composers for a plain list of lights: every light type, no shadows.

dvec3 shade_highlight(const Material& material, const std::vector<Light>& lights, const SurfacePoint& point) {
    const Composer compose = [&](const LitLights& lit) { return as_shade6(shade_highlight(material, lit, point)); };
    return shade_highlight(material, lit_lights(lights, point, compose, false, {}), point);
}

TranslucentShade shade_translucent(const Material& material, const std::vector<Light>& lights,
                                   const SurfacePoint& point) {
    const Composer compose = [&](const LitLights& lit) {
        const TranslucentShade shade = shade_translucent(material, lit, point);
        return as_shade6(shade.color, shade.transmittance);
    };
    return shade_translucent(material, lit_lights(lights, point, compose, false, {}), point);
}

dvec3 shade_metal(const Material& material, const std::vector<Light>& lights, const SurfacePoint& point) {
    const Composer compose = [&](const LitLights& lit) { return as_shade6(shade_metal(material, lit, point)); };
    return shade_metal(material, lit_lights(lights, point, compose, false, {}), point);
}

dvec3 shade_classic(const Material& material, const std::vector<Light>& lights, const SurfacePoint& point,
                    const dvec3& global_ambient) {
    const Composer compose = [&](const LitLights& lit) {
        return as_shade6(shade_classic(material, lit, point, global_ambient));
    };
    return shade_classic(material, lit_lights(lights, point, compose, is_lambertian(material), {}), point,
                         global_ambient);
}

}  // namespace m3055::ref
