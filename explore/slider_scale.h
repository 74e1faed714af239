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
#include <cstdlib>
#include <string>

namespace m3055::explore {

// A range starting at 0 is shown from this fraction of its top (7 decades);
// 0 itself is the slider's left end.
inline constexpr double kLogSliderDecades = 7.0;

// A light's intensity a_l in [0, 10]: 0.001 ... 10 on the slider (4 decades,
// about 37 px each at 150 px), 0 at its left end.
inline constexpr double kIntensityDecades = 4.0;

// The smallest positive value of the slider's scale (a range from 0: `decades` below hi).
inline double log_slider_floor(double lo, double hi, double decades = kLogSliderDecades) {
    return lo > 0.0 ? lo : hi * std::pow(10.0, -decades);
}

// value in [lo, hi] -> position in [0, 1] (0 exactly at lo).
inline double log_slider_position(double value, double lo, double hi, double decades = kLogSliderDecades) {
    const double floor = log_slider_floor(lo, hi, decades);
    if (value <= lo || hi <= floor) return 0.0;
    return std::clamp(std::log(std::max(value, floor) / floor) / std::log(hi / floor), 0.0, 1.0);
}

// position in [0, 1] -> value in [lo, hi] (the inverse of log_slider_position).
inline double log_slider_value(double position, double lo, double hi, double decades = kLogSliderDecades) {
    if (position <= 0.0) return lo;
    const double floor = log_slider_floor(lo, hi, decades);
    return std::clamp(floor * std::pow(hi / floor, std::min(position, 1.0)), lo, hi);
}

// Shift held while dragging a slider: the grab moves a tenth as fast as the
// mouse (as in Blender), from where it was when Shift went down.
inline constexpr double kFineDragFactor = 0.1;

// The slider position (0 ... 1) for a fine drag that began at
// `anchor_position` with the mouse at `anchor_x`, the mouse now at `mouse_x`,
// on a slider `width` pixels wide.
inline double fine_drag_position(double anchor_position, double anchor_x, double mouse_x, double width) {
    if (width <= 0.0) return anchor_position;
    return std::clamp(anchor_position + (mouse_x - anchor_x) / width * kFineDragFactor, 0.0, 1.0);
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

// A dragged value as the document keeps it: four significant digits (one
// more than the slider shows, so that each pixel of a Shift drag, a tenth of
// a pixel's 1-11 %, still moves it), within [lo, hi]. A scene saved after a
// drag then reads "m": 10.4, not the 10.398107170553497 of the pixel the
// mouse stopped on.
inline double dragged_value(double value, double lo, double hi) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3e", value);
    return std::clamp(std::strtod(text, nullptr), lo, hi);
}

}  // namespace m3055::explore
