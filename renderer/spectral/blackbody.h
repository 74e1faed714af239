// Planck's law: the spectral radiance of a black body (docs/spec.md#71-spectral-lights).
#pragma once

namespace m3055::spectral {

// The range of "temperature_k" a light may give.
inline constexpr double kMinKelvin = 1000.0;
inline constexpr double kMaxKelvin = 40000.0;

// B(lambda, T) = c1 / lambda^5 / (exp(c2 / (lambda T)) - 1), lambda in metres;
// c1 = 2 h c^2, c2 = h c / k (CODATA 2018, exact SI). Returned per metre of
// wavelength; only its shape matters here (lights are normalized to Y = 1).
double planck(double wavelength_nm, double kelvin);

}  // namespace m3055::spectral
