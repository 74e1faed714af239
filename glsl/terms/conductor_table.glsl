// Measured metals (docs/spec.md#72-measured-metals): reading a material's
// spectral table (passes/spectral_tables.h) in the material texture.
// C++ twin: reference/conductor.cpp sums the same per wavelength instead.

// A conductor's C0 for one light (docs/spec.md#72-measured-metals): its row of the
// material's spectral table (passes/spectral_tables.h), `samples` texels over
// cos(theta) = V.H in [0, 1], linearly interpolated (1 sample: F(lambda, 0)).
vec3 conductor_c0(int row, int samples, float VoH) {
    if (samples == 1) return m3055_material_texel(row).rgb;
    float x = clamp(VoH, 0.0, 1.0) * float(samples - 1);
    int s = min(int(x), samples - 2);
    return mix(m3055_material_texel(row + s).rgb, m3055_material_texel(row + s + 1).rgb, x - float(s));
}

