// The explorer's logarithmic sliders (explore/slider_scale.h): position
// and value are inverses, every decade gets the same room, and the text keeps
// three significant digits (a weight of 4.5e-5 must not read "0.0000").
#include "explore/slider_scale.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

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

// What a drag leaves in the document has four significant digits, stays in
// its range, and loses no pixel of a drag: on a 150 px slider with Shift held
// (1/1500 of it a pixel), neighbouring pixels give different values.
TEST(SliderScale, DraggedValueHasFourSignificantDigitsAndLosesNoPixel) {
    for (const auto& [lo, hi] : {std::pair{0.0, 100.0}, std::pair{1.0, 10000.0}, std::pair{0.0, 10.0}}) {
        double last = -1.0;
        for (int pixel = 0; pixel <= 1500; ++pixel) {
            const double v = dragged_value(log_slider_value(pixel / 1500.0, lo, hi), lo, hi);
            EXPECT_GE(v, lo);
            EXPECT_LE(v, hi);
            char text[32];
            std::snprintf(text, sizeof text, "%.3e", v);
            EXPECT_EQ(std::strtod(text, nullptr), v) << v;
            if (pixel > 0) EXPECT_GT(v, last) << lo << " " << hi << " " << pixel;
            last = v;
        }
    }
    EXPECT_EQ(dragged_value(10.398107170553497, 1.0, 10000.0), 10.4);
    EXPECT_EQ(dragged_value(4.49871e-5, 0.0, 100.0), 4.499e-5);
    EXPECT_EQ(dragged_value(9999.96, 1.0, 10000.0), 10000.0);
}

// A light's intensity on 4 decades (0.001 ... 10, 0 at
// the left end): from 0.4 the fill's 4:1 ratio (0.25) is a short, sure move.
TEST(SliderScale, IntensityHasFourDecadesAndRoomBetweenFillValues) {
    EXPECT_DOUBLE_EQ(log_slider_floor(0.0, 10.0, kIntensityDecades), 1e-3);
    EXPECT_EQ(log_slider_position(0.0, 0.0, 10.0, kIntensityDecades), 0.0);
    EXPECT_NEAR(log_slider_position(1.0, 0.0, 10.0, kIntensityDecades), 0.75, 1e-12);
    const double px = 150.0;  // the Lights panel's slider
    const double from_04_to_025 =
        (log_slider_position(0.4, 0.0, 10.0, kIntensityDecades) - log_slider_position(0.25, 0.0, 10.0, kIntensityDecades)) * px;
    EXPECT_GT(from_04_to_025, 7.0) << "pixels between 0.4 and 0.25 (the linear slider had 2)";
    EXPECT_NEAR(log_slider_value(log_slider_position(0.4, 0.0, 10.0, kIntensityDecades), 0.0, 10.0, kIntensityDecades), 0.4,
                1e-12);
    // 13 px from 0.4 (the slip to 0) is less than half a decade.
    EXPECT_GT(log_slider_value(log_slider_position(0.4, 0.0, 10.0, kIntensityDecades) - 13.0 / px, 0.0, 10.0,
                               kIntensityDecades),
              0.15);
}

TEST(SliderScale, ShiftDragMovesATenthAsFastFromWhereShiftWentDown) {
    EXPECT_DOUBLE_EQ(fine_drag_position(0.5, 100.0, 100.0, 150.0), 0.5);
    EXPECT_NEAR(fine_drag_position(0.5, 100.0, 250.0, 150.0), 0.6, 1e-12) << "the whole width: a tenth of it";
    EXPECT_NEAR(fine_drag_position(0.5, 100.0, 85.0, 150.0), 0.49, 1e-12);
    EXPECT_EQ(fine_drag_position(0.99, 0.0, 1000.0, 150.0), 1.0);
    EXPECT_EQ(fine_drag_position(0.01, 1000.0, 0.0, 150.0), 0.0);
}

}  // namespace
}  // namespace m3055::explore
