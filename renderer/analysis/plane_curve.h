// The explorer's polar plot, as numbers: a material's value for every view
// direction in the plane of a light and the normal N, for that light alone as
// a directional light at `incidence_deg` from N. ImGui-free (tests check it;
// app/explore_ui/polar_plot.cpp draws it).
//
// - A light behind the surface (incidence > 90 deg) lights nothing: the curve
//   is zero and light_behind says so (there is no clamp to 90 deg).
// - A translucent material's curve is what the display shows for it over the
//   background colour: the premultiplied colour plus the transmittance times
//   the background (docs/spec.md#42-translucent, Kay's opacity), so t_n and
//   t_p change it as they change the display.
#pragma once

#include "scene/scene.h"

#include <string>
#include <vector>

namespace m3055 {

struct PlaneCurve {
    double incidence_deg = 0.0;
    bool light_behind = false;  // N.L <= 0: this light adds nothing (opaque: the curve is 0)
    bool translucent = false;   // the values are the displayed blend over `background`
    std::vector<double> view_deg;  // -90 ... +90 from N; positive on the side away from L
    std::vector<dvec3> values;     // linear, unquantized, per view direction
    double max_value() const;      // the largest channel value (0 when empty)
    std::string quantity() const;  // what is plotted, in words (the plot's label)
};

// `steps` + 1 view directions, evenly from -90 to +90 degrees.
PlaneCurve plane_curve(const Material& material, const Light& light, double incidence_deg, const dvec3& background,
                       int steps = 180);

// The angle (degrees, 0 ... 180) between the normal facing the camera at its
// target (N = V) and the direction towards `light` there.
double incidence_at_target(const Light& light, const Camera& camera);

// The plot's radial scale, chosen by the user and kept until changed.
enum class RadialScale {
    fixed,      // linear, outer circle = `top` (1 = display white by default)
    model_max,  // linear, outer circle = the model's largest value over incidences 0-85 deg
    log,        // log10, from 1e-3 at the centre to `top` at the outer circle
    lobe,       // linear, outer circle = lobe_top of the curves shown (the default: the lobe fills the plot)
};
// A value's radius as a fraction of the outer circle (>= 0; > 1 is outside).
double radial_fraction(double value, RadialScale scale, double top);
// The largest value of `material` under `light` for incidences 0, 5, ... 85
// degrees (model_max's `top`: fixed while the user moves the light).
double model_max(const Material& material, const Light& light, const dvec3& background);
// The lobe scale's outer circle: the largest value of the curves shown (A's,
// and B's when given) rounded up to 1, 2 or 5 times a power of ten, so the
// circle's label is short and stays put while the value changes a little;
// 1 when the curves are black.
double lobe_top(const PlaneCurve& a, const PlaneCurve* b = nullptr);
double nice_ceiling(double value);

}  // namespace m3055
