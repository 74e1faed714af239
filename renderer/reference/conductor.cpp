#include "reference/conductor.h"

#include "spectral/cie_data.h"
#include "spectral/colorimetry.h"
#include "spectral/conductor.h"
#include "spectral/reflected_colour.h"

#include <glm/common.hpp>

namespace m3055::ref {

bool is_conductor(const Material& material) { return material.has("conductor") && material.choice("conductor") != 0; }

dvec3 conductor_c0(const Material& material, const Light* light, double cos_theta) {
    const spectral::ComplexIndex& metal = spectral::conductor(material.choice_name("conductor"));
    const bool full = light && material.choice_name("fresnel") == "full";
    const spectral::Power power =
        light ? spectral::light_power(light->temperature_k, light->illuminant) : spectral::light_power(0.0, "");
    // Eq. 2 per wavelength over the CIE 1931 table, for the light and for what the metal reflects.
    const spectral::Observer& cmf = spectral::cie1931_observer();
    dvec3 lit(0.0), seen(0.0);
    for (std::size_t i = 0; i < cmf.y.values.size(); ++i) {
        const double nm = cmf.y.start_nm + cmf.y.step_nm * double(i);
        const dvec3 bar(cmf.x.values[i], cmf.y.values[i], cmf.z.values[i]);
        const std::complex<double> eta = metal.at(nm);
        const double F = full ? spectral::conductor_fresnel(eta, cos_theta) : spectral::normal_reflectance(eta);
        lit += power(nm) * bar;
        seen += F * power(nm) * bar;
    }
    lit = glm::max(spectral::linear_srgb(lit), dvec3(0.0));
    seen = glm::max(spectral::linear_srgb(seen), dvec3(0.0));
    dvec3 c0(0.0);
    for (int c = 0; c < 3; ++c)
        if (lit[c] > 0.0) c0[c] = seen[c] / lit[c];
    return c0;
}

}  // namespace m3055::ref
