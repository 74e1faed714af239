// BRDF Explorer's views of any model as numbers, from the GPU grid
// (passes/brdf_grid.h, the renderer's own GLSL): the theta_h / theta_d image
// slice (Burley 2012), the directional albedo against the view angle, and the
// 3D lobe of f (N.L) for one incident direction. `m3055 plot` writes them as
// gnuplot scripts (app/plot_views.cpp); the explorer draws them in its "BRDF
// views" window (app/explore_ui/panel_brdf_views.cpp). No ImGui, no gnuplot here.
#pragma once

#include "passes/brdf_grid.h"
#include "scene/scene.h"

#include <memory>
#include <vector>

namespace m3055 {

// The largest channel of f[k]: what the views show of an RGB BRDF.
double channel_max(const std::vector<float>& f, std::size_t k);

// phi_d = 90 deg, n x n cells of 90/n degrees: theta_h across (i), theta_d up (j).
struct ThetaSlice {
    int n = 0;
    std::vector<double> f;      // [j * n + i]: the largest channel, as the GPU gave it
    std::vector<bool> below;    // L or V under the horizon there (shown as 0)
    double at(int i, int j) const { return f[std::size_t(j * n + i)]; }
    double max_value() const;   // over the cells above the horizon with finite values
};
ThetaSlice theta_slice(BrdfGrid& grid, const Material& material, int n = 90);

struct AlbedoCurve {
    std::vector<double> view_deg;  // 0, 1, ... 89
    std::vector<double> albedo;    // largest channel of the integral of f cos over the incident hemisphere
    std::size_t samples = 0;       // incident directions per view (cosine midpoint rule)
};
AlbedoCurve albedo_curve(BrdfGrid& grid, const Material& material, int n_mu = 64, int n_phi = 128);

// f (N.L) for L at `theta_in_deg` in the x-z plane (on the -x side) and V over
// the upper hemisphere: rows of constant theta_v (0 ... 90 deg, nt of them),
// columns of phi_v (0 ... 360 deg, np).
struct Lobe3d {
    dvec3 L{0.0};
    int nt = 46, np = 73;
    std::vector<dvec3> V;        // [t * np + p]
    std::vector<double> value;   // f (N.L), largest channel (non-finite or negative: 0)
    double top = 1.0;            // the largest value (1 when none is positive)
};
Lobe3d lobe_3d(BrdfGrid& grid, const Material& material, double theta_in_deg);

// The explorer's views of one material, computed when it (or, for the lobe,
// the incidence) changes and kept otherwise. The GL context must be current.
class BrdfViews {
public:
    // The grid's programs from `programs`, the context's shared cache.
    BrdfViews(const GlApi& gl, ProgramCache& programs);
    explicit BrdfViews(const GlApi& gl);  // with a program cache of its own
    ~BrdfViews();
    const ThetaSlice& slice(const Material& material);
    const AlbedoCurve& albedo(const Material& material);
    const Lobe3d& lobe(const Material& material, double theta_in_deg);
    long evaluations() const { return evaluations_; }  // how many views were computed

private:
    std::unique_ptr<BrdfGrid> grid_;
    Material slice_for_, albedo_for_, lobe_for_;
    double lobe_theta_ = -1.0;
    bool have_slice_ = false, have_albedo_ = false, have_lobe_ = false;
    ThetaSlice slice_;
    AlbedoCurve albedo_;
    Lobe3d lobe_;
    long evaluations_ = 0;
};

}  // namespace m3055
