#include "analysis/brdf_views.h"

#include "analysis/brdf_check.h"
#include "numeric/angles.h"

#include <algorithm>
#include <cmath>

namespace m3055 {

namespace {
using numeric::kPi;
double rad(double deg) { return deg * kPi / 180.0; }
}  // namespace

double channel_max(const std::vector<float>& f, std::size_t k) {
    return std::max({double(f[k * 3]), double(f[k * 3 + 1]), double(f[k * 3 + 2])});
}

double ThetaSlice::max_value() const {
    double top = 0.0;
    for (std::size_t k = 0; k < f.size(); ++k)
        if (!below[k] && std::isfinite(f[k])) top = std::max(top, f[k]);
    return top;
}

ThetaSlice theta_slice(BrdfGrid& grid, const Material& material, int n) {
    // Burley 2012: H = rot_y(theta_h) z, L = rot_y(theta_h) of the direction at
    // theta_d from z (phi_d = 90 deg), V its mirror about H.
    std::vector<dvec3> Ls, Vs;
    const double cell = 90.0 / n;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double th = rad((i + 0.5) * cell), td = rad((j + 0.5) * cell);
            const dvec3 d(0.0, std::sin(td), std::cos(td));
            const dvec3 L(d.x * std::cos(th) + d.z * std::sin(th), d.y, -d.x * std::sin(th) + d.z * std::cos(th));
            const dvec3 H(std::sin(th), 0.0, std::cos(th));
            Ls.push_back(L);
            Vs.push_back(2.0 * (H.x * L.x + H.y * L.y + H.z * L.z) * H - L);
        }
    const std::vector<float> f = grid.evaluate_pairs(material, Ls, Vs);
    ThetaSlice slice;
    slice.n = n;
    for (std::size_t k = 0; k < Ls.size(); ++k) {
        slice.f.push_back(channel_max(f, k));
        slice.below.push_back(Ls[k].z <= 0 || Vs[k].z <= 0);
    }
    return slice;
}

AlbedoCurve albedo_curve(BrdfGrid& grid, const Material& material, int n_mu, int n_phi) {
    const AlbedoSamples samples = albedo_samples(n_mu, n_phi);
    AlbedoCurve curve;
    for (int d = 0; d < 90; ++d) curve.view_deg.push_back(d);
    curve.samples = samples.L.size();
    curve.albedo = directional_albedo(grid.evaluate(material, samples.L, view_directions(curve.view_deg)), samples,
                                      curve.view_deg.size());
    return curve;
}

Lobe3d lobe_3d(BrdfGrid& grid, const Material& material, double theta_in_deg) {
    Lobe3d lobe;
    lobe.L = {-std::sin(rad(theta_in_deg)), 0.0, std::cos(rad(theta_in_deg))};
    for (int t = 0; t < lobe.nt; ++t)
        for (int p = 0; p < lobe.np; ++p) {
            const double th = rad(90.0 * t / (lobe.nt - 1)), ph = rad(360.0 * p / (lobe.np - 1));
            lobe.V.push_back({std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)});
        }
    const std::vector<float> f = grid.evaluate(material, {lobe.L}, lobe.V);
    double top = 0.0;
    for (std::size_t k = 0; k < lobe.V.size(); ++k) {
        const double v = channel_max(f, k) * lobe.L.z;
        lobe.value.push_back(std::isfinite(v) ? std::max(0.0, v) : 0.0);
        top = std::max(top, lobe.value.back());
    }
    lobe.top = top > 0 ? top : 1.0;
    return lobe;
}

BrdfViews::BrdfViews(const GlApi& gl, ProgramCache& programs) : grid_(std::make_unique<BrdfGrid>(gl, programs)) {}
BrdfViews::BrdfViews(const GlApi& gl) : grid_(std::make_unique<BrdfGrid>(gl)) {}
BrdfViews::~BrdfViews() = default;

const ThetaSlice& BrdfViews::slice(const Material& material) {
    if (!have_slice_ || !(material == slice_for_)) {
        slice_ = theta_slice(*grid_, material);
        slice_for_ = material, have_slice_ = true, ++evaluations_;
    }
    return slice_;
}

const AlbedoCurve& BrdfViews::albedo(const Material& material) {
    if (!have_albedo_ || !(material == albedo_for_)) {
        albedo_ = albedo_curve(*grid_, material);
        albedo_for_ = material, have_albedo_ = true, ++evaluations_;
    }
    return albedo_;
}

const Lobe3d& BrdfViews::lobe(const Material& material, double theta_in_deg) {
    if (!have_lobe_ || !(material == lobe_for_) || theta_in_deg != lobe_theta_) {
        lobe_ = lobe_3d(*grid_, material, theta_in_deg);
        lobe_for_ = material, lobe_theta_ = theta_in_deg, have_lobe_ = true, ++evaluations_;
    }
    return lobe_;
}

}  // namespace m3055
