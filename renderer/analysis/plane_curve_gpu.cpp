#include "analysis/plane_curve_gpu.h"

#include "models/model_spec.h"
#include "numeric/angles.h"
#include "passes/brdf_grid.h"

#include <algorithm>
#include <cmath>

namespace m3055 {

namespace {
using numeric::kPi;
using numeric::kDegree;

bool gpu_only(const Material& material) { return material.model().family == Family::brdf; }
}  // namespace

PlaneCurve brdf_plane_curve(BrdfGrid& grid, const Material& material, const Light& light, double incidence_deg,
                            int steps) {
    PlaneCurve curve;
    curve.incidence_deg = incidence_deg;
    const double cos_in = std::cos(incidence_deg * kDegree);
    curve.light_behind = cos_in <= 0.0;
    // The grid's frame: N = +z, the plane of incidence x-z (the default axis
    // gives X = +x), L on the -x side as the plot draws it.
    std::vector<dvec3> Vs;
    for (int i = 0; i <= steps; ++i) {
        const double view = -90.0 + 180.0 * i / steps;
        curve.view_deg.push_back(view);
        Vs.emplace_back(std::sin(view * kDegree), 0.0, std::cos(view * kDegree));
    }
    curve.values.assign(Vs.size(), dvec3(0.0));
    if (curve.light_behind) return curve;
    const dvec3 L(-std::sin(incidence_deg * kDegree), 0.0, cos_in);
    const std::vector<float> f = grid.evaluate(material, {L}, Vs);
    const dvec3 scale = kPi * cos_in * light.intensity * light.color;
    for (std::size_t k = 0; k < Vs.size(); ++k) {
        dvec3 value(f[k * 3], f[k * 3 + 1], f[k * 3 + 2]);
        value *= scale;
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(value[c])) value[c] = 0.0;  // as plane_curve: a NaN is no point
        curve.values[k] = value;
    }
    return curve;
}

PlaneCurves::PlaneCurves(const GlApi& gl, ProgramCache& programs)
    : grid_(std::make_unique<BrdfGrid>(gl, programs)) {}
PlaneCurves::PlaneCurves(const GlApi& gl) : grid_(std::make_unique<BrdfGrid>(gl)) {}
PlaneCurves::~PlaneCurves() = default;

PlaneCurve PlaneCurves::curve(const Material& material, const Light& light, double incidence_deg,
                              const dvec3& background) {
    if (!gpu_only(material)) return plane_curve(material, light, incidence_deg, background);
    const Key key{material, light.intensity, incidence_deg, light.color};
    if (!has_curve_ || !(key == curve_key_)) {
        curve_ = brdf_plane_curve(*grid_, material, light, incidence_deg);
        curve_key_ = key;
        has_curve_ = true;
        ++gpu_evaluations_;
    }
    return curve_;
}

double PlaneCurves::model_max(const Material& material, const Light& light, const dvec3& background) {
    if (!gpu_only(material)) return m3055::model_max(material, light, background);
    const Key key{material, light.intensity, 0.0, light.color};
    if (!has_max_ || !(key == max_key_)) {
        max_ = 0.0;
        for (int incidence = 0; incidence < 90; incidence += 5)
            max_ = std::max(max_, brdf_plane_curve(*grid_, material, light, incidence, 90).max_value());
        max_key_ = key;
        has_max_ = true;
        ++gpu_evaluations_;
    }
    return max_;
}

}  // namespace m3055
