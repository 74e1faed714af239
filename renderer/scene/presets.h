// Presets the explorer offers with one click, and the eq. 14 rescale of the
// metal lobe weights. Plain C++ (no UI): the explorer's buttons, its --script
// commands and the unit tests all call these same functions.
#pragma once

#include "scene/scene.h"

#include <string>
#include <vector>

namespace m3055 {

// ---- Light presets -------------------------------------------------------------
// Directions are world space for the default camera (+z towards the viewer,
// see light_direction.h).
enum class LightPreset {
    single_key,          // one white key light, upper right in front
    three_point_white,   // key (a = 1) + fill (a = 0.4) + back (a = 0.7), all white
    three_point_warm,    // the same with a warm (orange-ish) key
    three_point_cool,    // the same with a cool (blue-ish) key
    three_point_studio,  // the same lights as black bodies: a 3200 K (tungsten) key,
                         // 5600 K (daylight) fill and back (docs/spec.md#71-spectral-lights)
    paper_main_secondary // the paper's Fig. 11-13 set-up: main upper right (a = 1),
                         // secondary left and below (a = 0.7)
};

inline constexpr LightPreset kAllLightPresets[] = {
    LightPreset::single_key, LightPreset::three_point_white, LightPreset::three_point_warm,
    LightPreset::three_point_cool, LightPreset::three_point_studio, LightPreset::paper_main_secondary};

// Stable name used in scripts ("three_point_warm") and a label for the UI.
const char* preset_name(LightPreset preset);
const char* preset_label(LightPreset preset);
// Parses a preset_name(); returns false when unknown.
bool parse_light_preset(const std::string& name, LightPreset* preset);

// The lights of a preset (directional lights, no per-light lobes). Throws
// std::runtime_error for the studio preset when the CIE data (colord-data)
// cannot be read.
std::vector<Light> light_preset(LightPreset preset);

// Key-light colours of the three-point presets (c_l in [0,1]^3).
inline constexpr double kWarmKey[3] = {1.0, 0.82, 0.6};
inline constexpr double kCoolKey[3] = {0.65, 0.8, 1.0};

// ---- Eq. 14: highlight centre of the metal models -------------------------------
// The value of the specular sum at the highlight centre (alpha = 0, i.e. N = H,
// or R = V for metal_phong) for one light of a = 1, plus d:
//   metal:                    d + sum_j w_j / m_j^2      (Beckmann delta(m, 0) = 1/m^2)
//   metal_blinn, metal_phong: d + sum_j w_j              (cos^n 0 = 1)
// The paper chooses the weights so that this is 1 (eq. 14). Returns d for
// models without lobes (0 for those without d).
double highlight_peak(const Material& material);

// Scales every w_j by one factor so that highlight_peak(...) == 1 (eq. 14),
// keeping the lobes' proportions. Returns false and leaves the lobes alone
// when that is impossible: not a metal, no lobe weight to scale (sum 0),
// d >= 1, or a scaled weight would leave the weights' range (docs/spec.md#7-scene-files: [0, 100]).
bool rescale_to_eq14(Material& material);

// ---- Default scene -------------------------------------------------------------
// What the explorer shows when started without --scene: the docs/spec.md#7-scene-files example
// (a red highlight sphere on the M3055, one white light upper right).
Scene default_scene();

}  // namespace m3055
