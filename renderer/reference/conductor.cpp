#include "reference/conductor.h"

#include "scene/conductor_use.h"
#include "spectral/cie_data.h"
#include "spectral/colorimetry.h"
#include "spectral/conductor.h"
#include "spectral/reflected_colour.h"

#include <glm/common.hpp>

namespace m3055::ref {

bool is_conductor(const Material& material) { return conductor_use(material).has_value(); }

namespace {

// Eq. 2 per wavelength over the CIE 1931 table, for the light and for what the
// surface of reflectance F reflects of it; C0 per channel as the ratio.
template <typename Reflectance>
dvec3 c0_of(const Light* light, Reflectance F) {
    const spectral::Power power =
        light ? spectral::light_power(light->temperature_k, light->illuminant) : spectral::light_power(0.0, "");
    const spectral::Observer& cmf = spectral::cie1931_observer();
    dvec3 lit(0.0), seen(0.0);
    for (std::size_t i = 0; i < cmf.y.values.size(); ++i) {
        const double nm = cmf.y.start_nm + cmf.y.step_nm * double(i);
        const dvec3 bar(cmf.x.values[i], cmf.y.values[i], cmf.z.values[i]);
        lit += power(nm) * bar;
        seen += F(nm) * power(nm) * bar;
    }
    lit = glm::max(spectral::linear_srgb(lit), dvec3(0.0));
    seen = glm::max(spectral::linear_srgb(seen), dvec3(0.0));
    dvec3 c0(0.0);
    for (int c = 0; c < 3; ++c)
        if (lit[c] > 0.0) c0[c] = seen[c] / lit[c];
    return c0;
}

}  // namespace

dvec3 conductor_c0(const Material& material, const Light* light, double cos_theta) {
    const ConductorUse use = *conductor_use(material);
    const spectral::ComplexIndex& metal = spectral::conductor(use.metal);
    const ConductorFresnel fresnel = light ? use.fresnel : ConductorFresnel::normal;
    return c0_of(light, [&](double nm) { return conductor_F(fresnel, metal.at(nm), cos_theta); });
}

bool is_spectral(const Material& material) { return material.colour_spectrum() || is_conductor(material); }

dvec3 spectral_c0(const Material& material, const Light* light, double cos_theta) {
    if (const ReflectanceSpectrum* spectrum = material.colour_spectrum())
        return c0_of(light, [spectrum](double nm) { return spectrum->at(nm); });
    return conductor_c0(material, light, cos_theta);
}

}  // namespace m3055::ref
