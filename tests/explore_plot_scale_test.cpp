// The polar plot's scale as shown (explore/plot_scale.h): the user's choice,
// except A and B on the lobe scale with one peak more than four times the
// other's, which would leave the smaller a few pixels tall: log then, saying so.
#include "explore/plot_scale.h"

#include <gtest/gtest.h>

namespace m3055::explore {
namespace {

PlaneCurve flat(double value) {
    PlaneCurve curve;
    curve.view_deg = {-45.0, 0.0, 45.0};
    curve.values.assign(3, dvec3(value, value * 0.5, 0.0));
    return curve;
}

TEST(ExplorePlotScale, OneCurveAndCloseCurvesKeepTheChosenScale) {
    const PlaneCurve a = flat(5.0), b = flat(2.0);
    EXPECT_EQ(shown_scale(RadialScale::lobe, a, nullptr).scale, RadialScale::lobe);
    const ShownScale close = shown_scale(RadialScale::lobe, a, &b);
    EXPECT_EQ(close.scale, RadialScale::lobe);
    EXPECT_EQ(close.why, "");
}

TEST(ExplorePlotScale, APeakMoreThanFourTimesTheOthersShowsBothOnALogScaleAndSaysWhy) {
    const PlaneCurve a = flat(16.0), b = flat(1.0);
    const ShownScale shown = shown_scale(RadialScale::lobe, a, &b);
    EXPECT_EQ(shown.scale, RadialScale::log);
    EXPECT_EQ(shown.why, "log scale: A's peak is 16 x B's");
    EXPECT_EQ(shown_scale(RadialScale::lobe, b, &a).why, "log scale: B's peak is 16 x A's");
    EXPECT_EQ(shown_scale(RadialScale::lobe, flat(4.0), &b).scale, RadialScale::lobe) << "four times: still linear";
}

TEST(ExplorePlotScale, AScaleTheUserChoseIsNeverOverridden) {
    const PlaneCurve a = flat(16.0), b = flat(1.0);
    for (RadialScale chosen : {RadialScale::fixed, RadialScale::model_max, RadialScale::log})
        EXPECT_EQ(shown_scale(chosen, a, &b).scale, chosen);
    EXPECT_EQ(shown_scale(RadialScale::lobe, a, &b).scale, RadialScale::log);
    const PlaneCurve dark = flat(0.0);
    EXPECT_EQ(shown_scale(RadialScale::lobe, a, &dark).scale, RadialScale::lobe) << "nothing to compare with";
}

}  // namespace
}  // namespace m3055::explore
