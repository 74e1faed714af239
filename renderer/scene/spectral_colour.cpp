#include "scene/spectral_colour.h"

#include "spectral/reflected_colour.h"

namespace m3055 {

dvec3 spectrum_c0(const ReflectanceSpectrum& spectrum, const Light* light) {
    const spectral::Power power =
        light ? spectral::light_power(light->temperature_k, light->illuminant) : spectral::light_power(0.0, "");
    return spectral::reflected_c0(power, [&](double nm) { return spectrum.at(nm); });
}

}  // namespace m3055
