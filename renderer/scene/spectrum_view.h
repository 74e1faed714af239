// The spectra of a (light, material) pair as the explorer's Spectra plot and
// `m3055 plot spectrum` show them (docs/spec.md#74-the-spectra-in-use): the
// light's spectrum as the renderer uses it (a black body, a CIE illuminant,
// or D65 for a light given as RGB) and the material's reflectance R(lambda)
// (a measured metal at normal incidence, or its color_spectrum / kd_spectrum:
// a microfacet conductor with a kd_spectrum shows the kd's), with the
// words that say which. The numbers come from spectral::spectrum_curves.
#pragma once

#include "models/material.h"
#include "scene/scene.h"
#include "spectral/spectrum_curves.h"

#include <string>

namespace m3055 {

struct SpectrumView {
    spectral::SpectrumCurves curves;
    std::string light_label;        // "black body 3200 K", "CIE illuminant A", "D65 (an RGB light: ...)"
    std::string reflectance_label;  // "gold, R(lambda) at normal incidence", "color_spectrum", "kd_spectrum"; "" when none
    std::string no_reflectance;     // why there is no R(lambda) ("an RGB colour, no spectrum"); "" when there is one
    // The spectra's own colours, to draw each curve in: the light's (linear
    // sRGB at luminance 1, as the renderer uses it) and the reflectance's under
    // D65 (eq. 2's C0 of the pair; none without a reflectance).
    dvec3 light_colour{1.0, 1.0, 1.0};
    dvec3 reflectance_colour{0.0, 0.0, 0.0};
};

// `light` nullptr: D65 (the display's white); `material` nullptr: no reflectance.
// Throws spectral::SpectralError when the CIE data cannot be read.
SpectrumView spectrum_view(const Light* light, const Material* material);

}  // namespace m3055
