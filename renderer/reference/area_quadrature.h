// Adaptive quadrature over the directions in which a shaded point sees an
// area or sky light (docs/spec.md#75-area-lights-the-sky-and-shadows). The
// light is given as patches, each a map from the unit square to directions
// with their solid-angle density (reference/emitters.h); the engine cuts the
// patches into cells, integrates each cell by a 3 x 3 Gauss-Legendre rule
// (exact for polynomials of degree 5 in each variable), estimates its error
// by the 2 x 2 rule on the same cell (degree 3), and splits the cell with the
// largest estimate in four until the estimates sum to less than the tolerance
// times max(1, |value|) in every channel, or max_cells is reached. The
// integrand is the model itself: `value` says what a set of nodes adds to the
// shaded colour, so every model takes the light exactly as it takes a
// directional light (reference/lit_point.h).
//
// Sharp lobes (Phong n = 10000, Beckmann m = 0.001) can fall between every
// node of a coarse cell, where both rules see nothing: a cell near the peak
// direction (the mirror direction of V, where every lobe of the models here
// but Heidrich-Seidel's peaks) is also probed there, and split while the probe
// sees more than the rule's nodes. An anisotropic fibre highlight (Heidrich-
// Seidel) has no single peak and is found only by the cells' own nodes.
//
// Shadows make the integrand a step, which the rules converge on only as the
// cells' size. With `visible`, the cells start four a side of each patch, and
// each is also tested at its corners and the middles of its sides (visibility
// only). A cell whose shadow's edge runs from one side to another (found by
// bisection on the sides) is integrated on the edge's lit side of the chord
// between its crossings: each node weighs the lit part of its box, the error
// adds the area between chord and edge (from the edge's distance at the
// chord's middle) and the bisections' own; so an edge converges as the square
// of the cells' size. A cell with anything else across it (an occluder's
// corner, two edges) is split. An occluder's sliver that no node, corner or
// middle of a cell sees is missed.
#pragma once

#include "reference/reference.h"

#include <array>
#include <functional>
#include <vector>

namespace m3055::ref {

// What a patch gives at (u, v) in [0, 1]^2: the unit direction from the
// shaded point, the solid angle per unit area of (u, v), and how far the
// emitter is along it (infinity for the sky).
struct PatchSample {
    dvec3 direction;
    double density;
    double distance;
};
using Patch = std::function<PatchSample(double u, double v)>;

// One node of the quadrature: a direction and the solid angle it stands for.
struct QuadratureNode {
    dvec3 direction;
    double solid_angle;
    double distance;
};

// A colour and a transmittance (translucent models), or a colour and zeros.
using Shade6 = std::array<double, 6>;

struct AreaIntegrand {
    // What these nodes add to the shaded colour (the model with only them as lights, less `base`).
    std::function<Shade6(const std::vector<QuadratureNode>&)> value;
    // Whether the point sees the emitter along a node's direction (shadows); null: always.
    std::function<bool(const QuadratureNode&)> visible;
    Shade6 base{};      // the shaded colour without this light: the tolerance is relative to the whole
    dvec3 peak{0.0};    // the direction most lobes peak in (unit), or 0: none
};

// The nodes of the converged quadrature: their sum of value() is the light's
// share of the shaded colour. `stats` (optional) counts cells and nodes.
std::vector<QuadratureNode> integrate_area(const std::vector<Patch>& patches, const AreaIntegrand& integrand,
                                           const AreaQuadrature& options, AreaStats* stats);

}  // namespace m3055::ref
