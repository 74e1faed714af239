#include "explore/plot_scale.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace m3055::explore {

ShownScale shown_scale(RadialScale chosen, const PlaneCurve& a, const PlaneCurve* b) {
    if (chosen != RadialScale::lobe || !b) return {chosen, ""};
    const double peak_a = a.max_value(), peak_b = b->max_value();
    const double larger = std::max(peak_a, peak_b), smaller = std::min(peak_a, peak_b);
    if (!(smaller > 0.0) || larger <= kLobeRatioForLog * smaller) return {chosen, ""};
    char why[96];
    std::snprintf(why, sizeof why, "log scale: %s's peak is %.3g x %s's", peak_a > peak_b ? "A" : "B", larger / smaller,
                  peak_a > peak_b ? "B" : "A");
    return {RadialScale::log, why};
}

}  // namespace m3055::explore
