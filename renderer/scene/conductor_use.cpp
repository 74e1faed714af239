#include "scene/conductor_use.h"

#include "spectral/conductor.h"
#include "spectral/reflected_colour.h"

#include <algorithm>
#include <cmath>

namespace m3055 {

std::optional<ConductorUse> conductor_use(const Material& material) {
    if (!material.has("conductor") || material.choice("conductor") == 0) return std::nullopt;
    ConductorUse use;
    use.metal = material.choice_name("conductor");
    const std::string& fresnel = material.choice_name("fresnel");
    if (fresnel == "full" || fresnel == "dielectric") use.fresnel = ConductorFresnel::full;
    if (fresnel == "schlick") use.fresnel = ConductorFresnel::schlick;
    return use;
}

dvec3 conductor_d65_colour(const std::string& metal) {
    const spectral::ComplexIndex& index = spectral::conductor(metal);
    return spectral::reflected_c0(spectral::light_power(0.0, ""),
                                  [&index](double nm) { return spectral::normal_reflectance(index.at(nm)); });
}

double conductor_F(ConductorFresnel fresnel, std::complex<double> eta, double cos_theta) {
    switch (fresnel) {
        case ConductorFresnel::normal: return spectral::normal_reflectance(eta);
        case ConductorFresnel::schlick: {
            const double R = spectral::normal_reflectance(eta);
            return R + (1.0 - R) * std::pow(1.0 - std::clamp(cos_theta, 0.0, 1.0), 5.0);
        }
        case ConductorFresnel::full: return spectral::conductor_fresnel(eta, cos_theta);
    }
    return 0.0;
}

}  // namespace m3055
