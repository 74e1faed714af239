// A material colour given as a reflectance spectrum (docs/spec.md#73-spectral-colours):
// its colour under a light, eq. 2 for the pair.
#pragma once

#include "models/material.h"
#include "scene/scene.h"

namespace m3055 {

// C0 of the spectrum under `light`'s spectrum (nullptr: D65, the display's
// white; an RGB light stands for D65 too): spectral::reflected_c0.
dvec3 spectrum_c0(const ReflectanceSpectrum& spectrum, const Light* light);
// The same under D65: the colour the material shows as its "color".
inline dvec3 spectrum_d65_rgb(const ReflectanceSpectrum& spectrum) { return spectrum_c0(spectrum, nullptr); }

}  // namespace m3055
