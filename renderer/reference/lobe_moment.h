// The closed form of a Phong lobe over a spherical polygon: the integral of
// ((axis . u)+)^n over the directions u of a convex polygon above a point's
// horizon, n a whole number (Arvo 1995, "Applications of irradiance tensors to
// the simulation of non-Lambertian phenomena", the axial moments), and over a
// disk. A highlight (R_V . L)^m under a rect, a disk or the sky is such a lobe
// about V's mirror direction. GLSL twin: glsl/common/lobe_moment.glsl (same names).
#pragma once

#include "reference/reference.h"

#include <optional>
#include <vector>

namespace m3055::ref {

// The integral of (axis . u)^n dw over the directions u in every hemisphere
// {u : plane . u >= 0} of unit `planes` (their intersection: a convex region,
// empty or within the hemisphere of unit `pole`, which must be one of them);
// n >= 1. Its boundary is an arc of each plane's great circle, the part inside
// all the other hemispheres; the same circle twice counts once.
double lobe_integral_in_hemispheres(const std::vector<dvec3>& planes, const dvec3& pole, const dvec3& axis, int n);

// The integral of ((axis . u)+)^n dw over the directions u towards `corners`
// (from the origin, in order around a convex spherical polygon within a
// hemisphere, with `inside` a direction inside it) that lie above the horizons
// of unit N and unit `axis`; n >= 1: the hemispheres of the polygon's edges, N and axis.
double clipped_lobe_integral(const std::vector<dvec3>& corners, const dvec3& inside, const dvec3& N,
                             const dvec3& axis, int n);

// The integral of ((axis . u)+)^n dw over the directions u towards the disk
// c + cos t e0 + sin t e1 (c its centre from the origin, e0 and e1 its radii
// along two perpendicular axes) by the same recurrence with the rim for the
// boundary, integrated by the trapezoid rule with `nodes` nodes (the
// integrands are smooth and periodic); n >= 1. Only where the whole rim lies
// above the horizons of unit N and unit `axis`: std::nullopt elsewhere.
std::optional<double> disk_lobe_integral(const dvec3& c, const dvec3& e0, const dvec3& e1, const dvec3& N,
                                         const dvec3& axis, int n, int nodes);

// The sky's hemisphere about unit `up` as a polygon (inside it: up): four quarters of its horizon.
std::vector<dvec3> hemisphere_corners(const dvec3& up);

}  // namespace m3055::ref
