// The explorer's logarithmic sliders, without ImGui: where a value sits on
// the slider (0 ... 1) and back, and the text it shows. Values spanning
// decades (lobe weights after an eq. 14 rescale reach 1e-5, m reaches 1e4)
// get equal room per decade, and their text keeps three significant digits
// (scientific below 1e-3), so a small weight never reads as "0.0000".
// Header-only so tests/slider_scale_test.cpp can check it without a window.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace m3055::explore {

// A range starting at 0 is shown from this fraction of its top (7 decades);
// 0 itself is the slider's left end.
inline constexpr double kLogSliderDecades = 7.0;

// The smallest positive value of the slider's scale.
inline double log_slider_floor(double lo, double hi) {
    return lo > 0.0 ? lo : hi * std::pow(10.0, -kLogSliderDecades);
}

// value in [lo, hi] -> position in [0, 1] (0 exactly at lo).
inline double log_slider_position(double value, double lo, double hi) {
    const double floor = log_slider_floor(lo, hi);
    if (value <= lo || hi <= floor) return 0.0;
    return std::clamp(std::log(std::max(value, floor) / floor) / std::log(hi / floor), 0.0, 1.0);
}

// position in [0, 1] -> value in [lo, hi] (the inverse of log_slider_position).
inline double log_slider_value(double position, double lo, double hi) {
    if (position <= 0.0) return lo;
    const double floor = log_slider_floor(lo, hi);
    return std::clamp(floor * std::pow(hi / floor, std::min(position, 1.0)), lo, hi);
}

// Three significant digits; scientific below 1e-3; no exponent up to 1e5.
inline std::string significant_text(double value) {
    char text[32];
    const double magnitude = std::abs(value);
    if (value == 0.0) return "0";
    if (magnitude < 1e-3) std::snprintf(text, sizeof text, "%.2e", value);
    else if (magnitude >= 100.0) std::snprintf(text, sizeof text, "%.0f", value);
    else std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

}  // namespace m3055::explore
