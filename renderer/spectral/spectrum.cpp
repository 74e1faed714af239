#include "spectral/spectrum.h"

#include <cmath>

namespace m3055::spectral {

double Spectrum::at(double nm) const {
    if (values.empty() || nm < start_nm || nm > end_nm()) return 0.0;
    const double t = (nm - start_nm) / step_nm;
    const std::size_t i = static_cast<std::size_t>(std::floor(t));
    if (i + 1 >= values.size()) return values.back();
    const double f = t - double(i);
    return values[i] + f * (values[i + 1] - values[i]);
}

}  // namespace m3055::spectral
