#include "spectral/spectrum_curves.h"

#include "spectral/colorimetry.h"
#include "spectral/spectrum.h"

#include <algorithm>
#include <cmath>

namespace m3055::spectral {

SpectrumCurves spectrum_curves(const Power& light, const Power* reflectance) {
    const double y_light = xyz_of(light).y;
    if (!(y_light > 0.0)) throw SpectralError("the light's spectrum has no luminance (Y = 0)");
    const double scale = xyz_of([](double) { return 1.0; }).y / y_light;  // Y[E] / Y[S]
    SpectrumCurves curves;
    const int count = int(std::lround((kCurveEndNm - kCurveStartNm) / kCurveStepNm)) + 1;
    for (int i = 0; i < count; ++i) {
        const double nm = kCurveStartNm + kCurveStepNm * double(i);
        curves.nm.push_back(nm);
        curves.light.push_back(light(nm) * scale);
        if (reflectance) curves.reflectance.push_back((*reflectance)(nm));
    }
    return curves;
}

double peak_nm(const std::vector<double>& nm, const std::vector<double>& values) {
    const auto top = std::max_element(values.begin(), values.end());
    return top == values.end() ? 0.0 : nm[std::size_t(top - values.begin())];
}

}  // namespace m3055::spectral
