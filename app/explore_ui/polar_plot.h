// A polar plot of a material's value in the plane of incidence, drawn with
// ImGui's draw list from renderer/analysis/plane_curve.h (the numbers, tested
// there): the lobe shape beside the display.
#pragma once

#include "analysis/plane_curve.h"

namespace m3055::explore {

// Draws `curve` (one line per channel) with L on the left, N up, R dashed;
// radius by `scale` with `top` at the outer circle; values beyond it are drawn
// on the circle and the plot says so. `size` is the plot's width in pixels.
// `b`, when given (the A/B split), is drawn dashed in the same colours.
void polar_plot(const PlaneCurve& curve, RadialScale scale, double top, float size, const PlaneCurve* b = nullptr);

}  // namespace m3055::explore
