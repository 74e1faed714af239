// From a spectrum to the renderer's linear RGB (docs/spec.md#71-spectral-lights):
//   X = sum x-bar(l) S(l) dl, Y = sum y-bar(l) S(l) dl, Z = sum z-bar(l) S(l) dl
// over the CIE 1931 2-degree observer's grid (360-830 nm, 5 nm; CIE 15:2004
// section 7.1: summation at the table's interval), then linear sRGB (ITU-R
// BT.709 primaries, D65 white: IEC 61966-2-1), normalized to luminance Y = 1.
#pragma once

#include "spectral/spectrum.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <functional>
#include <string>

namespace m3055::spectral {

// CIE XYZ of a spectral power distribution given as a function of wavelength (nm).
glm::dvec3 xyz_of(const std::function<double(double)>& power);
glm::dvec3 xyz_of(const Spectrum& power);

// (x, y) = (X, Y) / (X + Y + Z).
glm::dvec2 chromaticity(const glm::dvec3& xyz);

// Linear sRGB of an XYZ (the matrix made, in double, from the sRGB primaries'
// and D65's chromaticities: R 0.64 0.33, G 0.30 0.60, B 0.15 0.06, W 0.3127 0.3290).
glm::dvec3 linear_srgb(const glm::dvec3& xyz);
// The luminance Y of a linear sRGB colour (the matrix's middle row).
double luminance(const glm::dvec3& rgb);

// A light's colour from its spectrum: linear sRGB scaled to luminance 1, so that
// a light's `intensity` keeps its meaning whatever its colour. A chromaticity
// outside sRGB's gamut (black bodies below about 1900 K: too red for the red
// primary) has a negative channel: it is clipped to 0 and the luminance made 1 again.
// Throws SpectralError for a spectrum with no luminance (Y <= 0).
glm::dvec3 light_rgb(const glm::dvec3& xyz);

// A black body at `kelvin` (Planck's law), and a CIE illuminant by name, as light_rgb.
// Throw SpectralError naming a data file when one is missing or malformed.
glm::dvec3 temperature_rgb(double kelvin);
// An illuminant's error names its file.
glm::dvec3 illuminant_rgb(const std::string& name);

}  // namespace m3055::spectral
