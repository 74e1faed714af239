// The CPU reference of a measured metal (docs/spec.md#72-measured-metals) and a
// colour spectrum (#73-spectral-colours), in
// wavelengths: C0 of a (conductor, light) pair summed per wavelength at the
// exact angle, independently of the GPU's precomputed tables
// (passes/spectral_tables.h), which tests/conductor_gpu_test.cpp holds against it.
#pragma once

#include "scene/scene.h"

namespace m3055::ref {

// Whether `material` names a conductor (a metal or microfacet with "conductor" other than "none").
bool is_conductor(const Material& material);

// C0 of the material's conductor under `light` (nullptr: the background's D65)
// at cos(theta) = V.H, F(lambda, theta) as scene/conductor_use.h says (the background:
// R(lambda) = ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2), normal incidence);
//   C0 = max(sRGB(sum xyz-bar R I dl), 0) / max(sRGB(sum xyz-bar I dl), 0) per channel.
dvec3 conductor_c0(const Material& material, const Light* light, double cos_theta);

// Whether the material's colour is spectral: a conductor, or a colour spectrum
// ("color_spectrum", docs/spec.md#73-spectral-colours).
bool is_spectral(const Material& material);
// C0 of either under `light` (nullptr: D65), per wavelength as above; a colour
// spectrum's is the same at every angle.
dvec3 spectral_c0(const Material& material, const Light* light, double cos_theta);

}  // namespace m3055::ref
