// The colours per (material, light) of measured metals (docs/spec.md#72-measured-metals)
// and colour spectra (#73-spectral-colours) for the GPU,
// appended to the material records in the same texture (passes/material_texture.h).
// A conductor material's table is, in texels (rgb used):
//   0                    C0 of the background term d: D65 at normal incidence; alpha: K
//   1 + i K + s          light i's C0 at cos(theta) = s / (K - 1), s = 0 .. K - 1
// with K = 1 for F(lambda, 0) alone (the metals' "normal", microfacet's "none") and
// K = spectral::kConductorCosSamples when F depends on the angle; light i is the shader's i-th light
// (passes/light_uniforms.h: reaches_shader). A classic model's table (microfacet's
// conductor in place of ks, any classic model's kd_spectrum) is laid out as
//   0                    (kd's start or -1, 0, 0, K: the conductor's texels a light, 0 for none)
//   1 + i K + s          the conductor's C0 for light i, as above
//   kd's start + i       kd_spectrum's colour under light i (docs/spec.md#73-spectral-colours).
// Its start (a texel index) goes into
// the record's spectral_table float (-1 elsewhere); glsl/models/metal.glsl reads it.
#pragma once

#include "scene/scene.h"

#include <vector>

namespace m3055 {

// Appends the tables of the spectral materials among `materials` (records:
// one each, pack_material's, passes/material_slots.h) and points their records at them. Tables
// of metals are computed once per (metal, fresnel, light spectrum) and kept for
// the process; a colour spectrum's (one texel per light) each time. Throws spectral::SpectralError when the CIE data cannot be read.
void append_spectral_tables(const std::vector<const Material*>& materials, const std::vector<Light>& lights,
                            std::vector<float>& records);

}  // namespace m3055
