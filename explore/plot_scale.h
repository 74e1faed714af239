// The polar plot's scale as shown: the user's choice, except that in the A/B
// split with the lobe scale (the default) a curve more than kLobeRatioForLog
// times the other's peak would leave the smaller one a few pixels tall, so
// the plot is logarithmic then, and says so. No ImGui: tested without a window.
#pragma once

#include "analysis/plane_curve.h"

#include <string>

namespace m3055::explore {

inline constexpr double kLobeRatioForLog = 4.0;

struct ShownScale {
    RadialScale scale = RadialScale::lobe;
    std::string why;  // "" when the user's choice is shown; else one line saying why not
};

// What the plot shows A (and B, when `b` is given) with, the user having chosen `chosen`.
ShownScale shown_scale(RadialScale chosen, const PlaneCurve& a, const PlaneCurve* b);

}  // namespace m3055::explore
