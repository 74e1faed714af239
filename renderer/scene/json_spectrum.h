// A material colour given as a reflectance spectrum (docs/spec.md#73-spectral-colours):
//   "color_spectrum": {"nm": [380, 400, ...], "values": [0.1, 0.12, ...]}
// read with validation and written back.
#pragma once

#include "models/material.h"
#include "scene/json_node.h"

namespace m3055::scene_json {

// The accepted wavelengths, nm, and the most samples.
inline constexpr double kSpectrumMinNm = 380.0, kSpectrumMaxNm = 780.0;
inline constexpr std::size_t kSpectrumMaxSamples = 1000;

// "nm": 2 to 1000 finite wavelengths in [380, 780], increasing; "values": as
// many reflectances in [0, 1]. Errors name the field: "color_spectrum.nm[3]: ...".
ReflectanceSpectrum read_spectrum(const Node& node);
json spectrum_json(const ReflectanceSpectrum& spectrum);

}  // namespace m3055::scene_json
