// The colour a spectral reflectance takes under a light (docs/spec.md#72-measured-metals):
// eq. 2 of the paper done per wavelength for one (material, light) pair.
#pragma once

#include <glm/vec3.hpp>

#include <functional>
#include <string>

namespace m3055::spectral {

using Power = std::function<double(double)>;  // of the wavelength, nm

// The spectrum a light stands for: a black body at `kelvin` when > 0, else the
// CIE illuminant `illuminant` when not empty, else D65 — a light given as an
// RGB `color` is D65 (the display's white) with its channels scaled by that
// colour. Throws SpectralError naming a missing data file.
Power light_power(double kelvin, const std::string& illuminant);

// C0 of a surface with reflectance F(lambda) under light I(lambda), per channel:
//   C0 = max(sRGB(XYZ[F I]), 0) / max(sRGB(XYZ[I]), 0)   (0 where the light's channel is 0),
// XYZ[S] = sum over the CIE 1931 table (360-830 nm, 5 nm) of (x-bar, y-bar, z-bar) S.
// The light's own colour c_l is sRGB(XYZ[I]) at luminance 1, so a_l c_l C0 is
// a_l sRGB(XYZ[F I]) / Y[I]: eq. 2 for the pair, in the renderer's RGB form.
glm::dvec3 reflected_c0(const Power& light, const Power& reflectance);

}  // namespace m3055::spectral
