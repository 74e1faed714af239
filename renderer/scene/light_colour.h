// Where a light's colour comes from, and changing it as the explorer's Lights
// panel does: an RGB colour, a black body at a temperature (kelvin), or a CIE
// standard illuminant (docs/spec.md#71-spectral-lights). A spectral light's
// RGB is computed here as the loader computes it (spectral::temperature_rgb,
// illuminant_rgb), so an edited scene renders as the same scene saved and
// loaded again.
#pragma once

#include "scene/scene.h"

#include <string>
#include <vector>

namespace m3055 {

enum class LightColourSource { rgb, temperature, illuminant };

// The black bodies the format allows (spectral::kMinKelvin ... kMaxKelvin).
inline constexpr double kMinLightKelvin = 1000.0, kMaxLightKelvin = 40000.0;

LightColourSource colour_source(const Light& light);

// An RGB light of colour `rgb` (each channel clamped to [0, 1], as the format requires).
void set_rgb_colour(Light& light, const dvec3& rgb);
// A black body at `kelvin`, clamped to [spectral::kMinKelvin, kMaxKelvin].
// False, with the reason in `error`, when the CIE data cannot be read
// (colord-data missing); the light is then unchanged.
bool set_temperature(Light& light, double kelvin, std::string* error);
// CIE illuminant `name` (one of light_illuminant_names()); false as above.
bool set_illuminant(Light& light, const std::string& name, std::string* error);

const std::vector<std::string>& light_illuminant_names();

}  // namespace m3055
