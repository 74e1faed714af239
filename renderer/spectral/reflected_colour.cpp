#include "spectral/reflected_colour.h"

#include "spectral/blackbody.h"
#include "spectral/cie_data.h"
#include "spectral/colorimetry.h"

#include <glm/common.hpp>

namespace m3055::spectral {

Power light_power(double kelvin, const std::string& illuminant) {
    if (kelvin > 0.0) return [kelvin](double nm) { return planck(nm, kelvin); };
    const Spectrum* table = &cie_illuminant(illuminant.empty() ? std::string("D65") : illuminant);
    return [table](double nm) { return table->at(nm); };
}

glm::dvec3 reflected_c0(const Power& light, const Power& reflectance) {
    const glm::dvec3 lit = glm::max(linear_srgb(xyz_of(light)), glm::dvec3(0.0));
    const glm::dvec3 seen =
        glm::max(linear_srgb(xyz_of([&](double nm) { return light(nm) * reflectance(nm); })), glm::dvec3(0.0));
    glm::dvec3 c0(0.0);
    for (int c = 0; c < 3; ++c)
        if (lit[c] > 0.0) c0[c] = seen[c] / lit[c];
    return c0;
}

}  // namespace m3055::spectral
