// Where a shaded point sees an area or sky light (docs/spec.md#75-area-lights-the-sky-and-shadows):
// the directions in front of the emitter and above the point's horizon, as
// smooth patches for the quadrature (reference/area_quadrature.h), and the
// closed forms of their projected solid angle where one exists.
//
// The horizon cuts the emitter exactly, so no patch straddles it and the
// integrand is smooth on each (what a model adds falls to 0 at the horizon):
// a rect is clipped to the polygon above the horizon and fanned into
// triangles from its centroid, each mapped from the square by Duffy's
// transform; a disk cut by the horizon's line is the segment beyond a chord,
// swept in strips parallel to it; the sky seen above the horizon is a lune,
// the meeting of two hemispheres, in longitude and latitude about the line
// where their horizons meet.
#pragma once

#include "reference/area_quadrature.h"
#include "reference/reference.h"

#include <optional>
#include <vector>

namespace m3055::ref {

// The patches of `light` (rect, disk or sky) seen from `point`; none when the
// point is behind the emitter's plane or the emitter is below its horizon.
std::vector<Patch> emitter_patches(const Light& light, const SurfacePoint& point);

// The projected solid angle, the integral of (N.w)+ over the directions w in
// which the point sees the light: what a Lambert surface integrates. Exact for
// a rect (Lambert's formula for the polygon clipped to the horizon) and the sky
// (the lune: pi (1 + N.up) / 2); none for a disk.
std::optional<double> projected_solid_angle(const Light& light, const SurfacePoint& point);

// Lambert's formula: the projected solid angle about unit `N` of the polygon
// `corners` (in order, all at or above the horizon of `N` at `P`), the sum over
// its edges of the angle each subtends times N . (the unit normal of the plane
// through P and the edge) / 2 (Lambert 1760; Arvo 1995, "Applications of
// irradiance tensors", eq. 1).
double polygon_projected_solid_angle(const std::vector<dvec3>& corners, const dvec3& P, const dvec3& N);

}  // namespace m3055::ref
