// The spectra in use, as curves to plot (docs/spec.md#74-the-spectra-in-use):
// a light's spectral power as the renderer normalizes it, and a material's
// reflectance R(lambda), over the visible range. The explorer's Spectra plot
// and `m3055 plot spectrum` both draw these numbers (scene/spectrum_view.h
// picks the light and the material).
#pragma once

#include "spectral/reflected_colour.h"

#include <vector>

namespace m3055::spectral {

// The plotted range: 380-780 nm every 5 nm (the CIE observer's own step).
inline constexpr double kCurveStartNm = 380.0, kCurveEndNm = 780.0, kCurveStepNm = 5.0;

struct SpectrumCurves {
    std::vector<double> nm;           // 380, 385, ..., 780
    // The light's S(lambda) at luminance Y = 1, as the renderer scales every
    // light (§7.1 step 3), in units where the equal-energy illuminant E is 1:
    //   S(lambda) Y[E] / Y[S],  Y[S] = sum y-bar S dlambda over the CIE table.
    // So two lights of equal intensity plot with equal luminance-weighted area.
    std::vector<double> light;
    std::vector<double> reflectance;  // R(lambda) at nm; empty when no reflectance was given
};

// `light`: a light's spectrum (light_power); `reflectance`: nullptr for none.
// Throws SpectralError when the CIE data cannot be read, or for a light with no luminance.
SpectrumCurves spectrum_curves(const Power& light, const Power* reflectance);

// The wavelength of the largest value of `values` (sampled at `nm`): where a curve peaks.
double peak_nm(const std::vector<double>& nm, const std::vector<double>& values);

}  // namespace m3055::spectral
