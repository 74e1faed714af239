#include "spectral/blackbody.h"

#include <cmath>

namespace m3055::spectral {

namespace {
// h = 6.62607015e-34 J s, c = 299792458 m/s, k = 1.380649e-23 J/K (SI 2019, exact).
constexpr double kH = 6.62607015e-34;
constexpr double kC = 299792458.0;
constexpr double kK = 1.380649e-23;
constexpr double kC1 = 2.0 * kH * kC * kC;  // W m^2 / sr
constexpr double kC2 = kH * kC / kK;        // m K, 1.438777e-2
}  // namespace

double planck(double wavelength_nm, double kelvin) {
    const double lambda = wavelength_nm * 1e-9;
    // expm1 keeps the long-wavelength end exact (c2 / (lambda T) small).
    return kC1 / std::pow(lambda, 5) / std::expm1(kC2 / (lambda * kelvin));
}

}  // namespace m3055::spectral
