// The explorer's polar-plot numbers for any model. Built-in models have a CPU
// reference (plane_curve.h); a .brdf file's model is GLSL only, so its curve
// is evaluated on the GPU by the grid pass (passes/brdf_grid.h) that `m3055
// plot` and brdf-check use. No ImGui here: app/explore_ui/panel_plot.cpp draws it.
#pragma once

#include "analysis/plane_curve.h"
#include "gl/gl_api.h"
#include "gl/program.h"

#include <memory>

namespace m3055 {

class BrdfGrid;

// A .brdf model's curve as plane_curve() defines it for an opaque model: per
// view direction, pi f(L, V) (N.L) a_l c_l of `light` alone as a directional
// light at `incidence_deg` (the .brdf shading convention, docs/brdf-files.md).
PlaneCurve brdf_plane_curve(BrdfGrid& grid, const Material& material, const Light& light, double incidence_deg,
                            int steps = 180);

// plane_curve() or brdf_plane_curve() by the material's family. The GPU curves
// are kept with their inputs, so a frame that changes neither the material,
// the light nor the angle evaluates nothing. Needs the GL context current.
class PlaneCurves {
public:
    // The grid's programs from `programs`, the context's shared cache.
    PlaneCurves(const GlApi& gl, ProgramCache& programs);
    explicit PlaneCurves(const GlApi& gl);  // with a program cache of its own
    ~PlaneCurves();
    PlaneCurve curve(const Material& material, const Light& light, double incidence_deg, const dvec3& background);
    // model_max() of plane_curve.h for any model (the plot's "model max" scale).
    double model_max(const Material& material, const Light& light, const dvec3& background);
    long gpu_evaluations() const { return gpu_evaluations_; }  // how often the grid ran (tests)

private:
    struct Key {
        Material material;
        double intensity = 0.0, incidence = 0.0;
        dvec3 color{0.0};
        bool operator==(const Key& o) const {
            return material == o.material && intensity == o.intensity && incidence == o.incidence && color == o.color;
        }
    };
    std::unique_ptr<BrdfGrid> grid_;
    Key curve_key_, max_key_;
    PlaneCurve curve_;
    double max_ = 0.0;
    bool has_curve_ = false, has_max_ = false;
    long gpu_evaluations_ = 0;
};

}  // namespace m3055
