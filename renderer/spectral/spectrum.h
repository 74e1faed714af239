// A spectrum sampled at evenly spaced wavelengths (docs/spec.md#71-spectral-lights).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace m3055::spectral {

// what(): one line "FILE: problem" (a data file missing or malformed).
class SpectralError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct Spectrum {
    double start_nm = 0.0;       // wavelength of values[0]
    double step_nm = 5.0;        // spacing, > 0
    std::vector<double> values;  // at start_nm + i step_nm

    double end_nm() const { return start_nm + step_nm * double(values.size() - 1); }
    // Linearly interpolated; 0 outside [start_nm, end_nm] (no light, no response there).
    double at(double nm) const;
};

}  // namespace m3055::spectral
