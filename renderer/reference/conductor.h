// The CPU reference of a measured metal (docs/spec.md#72-measured-metals), in
// wavelengths: C0 of a (conductor, light) pair summed per wavelength at the
// exact angle, independently of the GPU's precomputed tables
// (passes/spectral_tables.h), which tests/conductor_gpu_test.cpp holds against it.
#pragma once

#include "scene/scene.h"

namespace m3055::ref {

// Whether `material` names a conductor (a metal model with "conductor" other than "none").
bool is_conductor(const Material& material);

// C0 of the material's conductor under `light` (nullptr: the background's D65)
// at cos(theta) = V.H: with "fresnel": "normal" (and for the background) R(lambda) =
// ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2), with "full" the complex eq. 19 at cos_theta;
//   C0 = max(sRGB(sum xyz-bar R I dl), 0) / max(sRGB(sum xyz-bar I dl), 0) per channel.
dvec3 conductor_c0(const Material& material, const Light* light, double cos_theta);

}  // namespace m3055::ref
