// The lights at one shaded point as the families' composers sum them
// (LitLights, reference/reference.h; docs/spec.md#75-area-lights-the-sky-and-shadows):
// a directional, point or spot light as its sample, blocked (scale 0) where a
// shadow falls; an area or sky light as the nodes of its quadrature, each a
// directional light from its direction with scale L c dw, so that every model
// takes an area light exactly as it takes a directional one.
#pragma once

#include "reference/area_quadrature.h"
#include "reference/reference.h"

#include <functional>
#include <vector>

namespace m3055::ref {

// What a family's composer makes of lights at the point: the colour, then the
// transmittance of a translucent model (zeros for an opaque one).
using Composer = std::function<Shade6(const LitLights&)>;

// `lights` at `point`: each directional, point and spot light sampled (with
// `shadow`, at scale 0 when options.occluders block the way to it), then each
// enabled area or sky light as nodes: for a Lambert surface (`lambertian`)
// under a rect or the sky with nothing to block it, one node along N weighted
// by the exact projected solid angle (reference/emitters.h); otherwise the
// nodes of the adaptive quadrature, whose integrand is `compose` itself.
LitLights lit_lights(const std::vector<Light>& lights, const SurfacePoint& point, const Composer& compose,
                     bool lambertian, const LightingOptions& options);

// Whether a material answers a light from L with (N.L)+ times a colour of
// its own (a classic material whose diffuse term is Lambert's and which has no
// specular term): what the closed forms integrate.
bool is_lambertian(const Material& material);

// Whether any light of `lights` needs more than sampling: an area or sky
// light, or a shadow where there are occluders.
bool needs_lit_lights(const std::vector<Light>& lights, const LightingOptions& options);

}  // namespace m3055::ref
