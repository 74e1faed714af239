// `m3055 plot`: BRDF Explorer's views of any model as gnuplot scripts with
// their data inline (the data from passes/brdf_grid.h, the renderer's own
// GLSL): the polar plot in the plane of incidence (linear or log, several
// models overlaid), the theta_h / theta_d image slice (Burley 2012), the
// directional albedo against the view angle, and the 3D lobe for one incident
// direction.
#pragma once

#include "analysis/brdf_target.h"
#include "passes/brdf_grid.h"

#include <string>
#include <vector>

namespace m3055::plot {

struct ViewOptions {
    double theta_in_deg = 45;  // incident angle (polar, lobe)
    bool log = false;          // polar: log10 radius over 4 decades; slice: log10 colour
    int albedo_mu = 64, albedo_phi = 128;  // albedo: incident samples (cosine midpoint)
};

// Each returns the whole gnuplot script (pngcairo into the variable `out`).
std::string polar_script(BrdfGrid& grid, const std::vector<BrdfTarget>& targets, const ViewOptions& o);
std::string slice_script(BrdfGrid& grid, const BrdfTarget& target, const ViewOptions& o);
std::string albedo_script(BrdfGrid& grid, const std::vector<BrdfTarget>& targets, const ViewOptions& o);
std::string lobe_script(BrdfGrid& grid, const BrdfTarget& target, const ViewOptions& o);

}  // namespace m3055::plot
