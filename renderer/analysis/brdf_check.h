// The measurements of `m3055 brdf-check` over a BRDF evaluated on a grid
// (passes/brdf_grid.h): NaN, Inf and negative values, Helmholtz reciprocity,
// directional albedo (the white furnace), and for a model with a normalized
// microfacet distribution, the integral of D (N.h). Pure numbers: the caller
// evaluates f (on the GPU) at the directions given here.
#pragma once

#include "models/material.h"
#include "scene/scene.h"

#include <optional>
#include <vector>

namespace m3055 {

// Directions of the upper hemisphere of N = +z for the value and reciprocity
// checks: theta at n_theta steps from 0 to 90 degrees inclusive (normal and
// exactly grazing), phi at n_phi steps, plus the pole once.
std::vector<dvec3> check_directions(int n_theta, int n_phi);

struct GridStats {
    long nonfinite = 0, negative = 0, values = 0;  // with L and V above the horizon (z > 0)
    long grazing_nonfinite = 0;                     // NaN/Inf with V exactly grazing (N.V = 0)
    long first_bad = -1;                            // index (j * n + i) of the first NaN/Inf/negative inside
    long first_setting = -1;                        // merge(): the setting it came from
    double max_value = 0;           // largest finite f
    double max_reciprocity = 0;     // max |f(L,V) - f(V,L)| / max(|f(L,V)|, |f(V,L)|), both L.z, V.z > 0
};
// f: RGB per (L_i, V_j) for L and V both `dirs` (so f(V, L) is the transpose).
GridStats grid_stats(const std::vector<float>& f, const std::vector<dvec3>& dirs);
// Folds b, measured at setting `setting`, into a (counts add, maxima are the larger).
void merge(GridStats& a, const GridStats& b, long setting);

// Incident directions for the albedo integral, cosine-midpoint: mu = cos theta
// in n_mu cells, phi in n_phi cells; each sample's weight mu dmu dphi.
struct AlbedoSamples {
    std::vector<dvec3> L;
    std::vector<double> weight;
};
AlbedoSamples albedo_samples(int n_mu, int n_phi);
// The view directions (phi = 0) at `degrees` from the normal.
std::vector<dvec3> view_directions(const std::vector<double>& degrees);
// Directional albedo per view: max over channels of sum_i f(L_i, V_j) weight_i.
std::vector<double> directional_albedo(const std::vector<float>& f, const AlbedoSamples& samples, std::size_t views);

// For models declaring a normalized distribution (microfacet): the integral
// of sum_j w_j D_j (N.h) over the hemisphere, by the CPU reference's D (same
// formulas as the GLSL), and sum_j w_j (what it should equal). Empty otherwise.
struct DistributionIntegral {
    double integral = 0, weights = 0;
};
std::optional<DistributionIntegral> distribution_integral(const Material& material);

}  // namespace m3055
