// Measured metals (docs/spec.md#72-measured-metals): a metal's complex refractive
// index N(lambda) = n + i k from a published table (data/conductors/NAME.nk, the
// source cited in each file), and the paper's Fresnel reflectance eq. 19 extended
// to a complex index.
#pragma once

#include <complex>
#include <string>
#include <vector>

namespace m3055::spectral {

// Samples of a conductor's colour over cos(theta) in [0, 1], evenly spaced
// (the GPU's table for "fresnel": "full", passes/spectral_tables.h; the GLSL
// constant CONDUCTOR_COS_SAMPLES).
inline constexpr int kConductorCosSamples = 65;

// A table of n(lambda), k(lambda): linearly interpolated, held at its end
// values outside the table (every table covers 360-830 nm).
struct ComplexIndex {
    std::vector<double> nm, n, k;  // wavelengths increasing
    std::complex<double> at(double wavelength_nm) const;
};

// Parses a .nk file: '#' comment lines, then rows "wavelength_um n k" with
// increasing wavelengths, n > 0, k >= 0, at least two rows, covering 360-830 nm.
// Throws SpectralError "SOURCE: line L: problem".
ComplexIndex parse_conductor(const std::string& text, const std::string& source);

// The metals' names ("aluminium", "chromium", "copper", "gold", ...), sorted.
const std::vector<std::string>& conductor_names();
// The metal's table (parsed once); SpectralError for an unknown name.
const ComplexIndex& conductor(const std::string& name);

// Normal-incidence reflectance ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2): the
// paper's F(lambda, 0) = R(lambda) of assumption 3.
double normal_reflectance(std::complex<double> eta);

// Unpolarized Fresnel reflectance from air onto a medium of complex index eta
// at incidence cos_theta in [0, 1]: the paper's eq. 19 with complex g,
//   F = 1/2 |g - c|^2 / |g + c|^2 {1 + |c (g + c) - 1|^2 / |c (g - c) + 1|^2},
//   g = sqrt(eta^2 + c^2 - 1), c = cos_theta
// (the identity behind eq. 19 is algebraic, so it holds for complex eta with
// moduli in place of squares; k = 0 gives eq. 19 exactly). 1 at c = 0.
double conductor_fresnel(std::complex<double> eta, double cos_theta);

}  // namespace m3055::spectral
