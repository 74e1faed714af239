// The explorer's logarithmic sliders (explore/slider_scale.h): position
// and value are inverses, every decade gets the same room, and the text keeps
// three significant digits (issue 12: a weight of 4.5e-5 read "0.0000").
#include "explore/slider_scale.h"

#include <gtest/gtest.h>

namespace m3055::explore {
namespace {

TEST(SliderScale, PositionAndValueAreInverses) {
    for (const auto& [lo, hi] : {std::pair{0.0, 100.0}, std::pair{0.01, 10.0}, std::pair{1.0, 10000.0}}) {
        EXPECT_EQ(log_slider_position(lo, lo, hi), 0.0);
        EXPECT_EQ(log_slider_value(0.0, lo, hi), lo);
        EXPECT_NEAR(log_slider_value(1.0, lo, hi), hi, 1e-12 * hi);
        for (double v : {4.5e-5, 1e-3, 0.1, 1.0, 43.56, 99.0}) {
            if (v < log_slider_floor(lo, hi) || v > hi) continue;
            EXPECT_NEAR(log_slider_value(log_slider_position(v, lo, hi), lo, hi), v, 1e-9 * v) << lo << " " << hi;
        }
    }
}

TEST(SliderScale, EveryDecadeGetsTheSameRoom) {
    // A weight in [0, 100] (the paper's lobes): 7 decades from 1e-5, each 1/7 of the slider.
    const double step = log_slider_position(1.0, 0.0, 100.0) - log_slider_position(0.1, 0.0, 100.0);
    EXPECT_NEAR(step, 1.0 / kLogSliderDecades, 1e-12);
    EXPECT_NEAR(log_slider_position(1e-3, 0.0, 100.0) - log_slider_position(1e-4, 0.0, 100.0), step, 1e-12);
    // 4.5e-5, what the eq. 14 rescale gives, sits above 0 on the slider.
    EXPECT_GT(log_slider_position(4.5e-5, 0.0, 100.0), 0.0);
}

TEST(SliderScale, TextKeepsThreeSignificantDigits) {
    EXPECT_EQ(significant_text(4.5e-5), "4.50e-05");
    EXPECT_EQ(significant_text(0.0), "0");
    EXPECT_EQ(significant_text(0.00123), "0.00123");
    EXPECT_EQ(significant_text(0.1), "0.1");
    EXPECT_EQ(significant_text(43.56), "43.6");
    EXPECT_EQ(significant_text(1234.4), "1234");
}

}  // namespace
}  // namespace m3055::explore
