#include "reference/conductor.h"

#include "scene/conductor_use.h"
#include "spectral/cie_data.h"
#include "spectral/colorimetry.h"
#include "spectral/conductor.h"
#include "spectral/reflected_colour.h"

#include <glm/common.hpp>

#include <string>
#include <vector>

namespace m3055::ref {

bool is_conductor(const Material& material) { return conductor_use(material).has_value(); }

namespace {

// A light's power at each wavelength of the CIE 1931 table and its own colour
// (the denominator of C0), kept per light: c0_of below is called per pixel and
// light, and evaluating Planck's law there twice per wavelength was a third of
// a spectral reference render. The numbers, and the order they are summed in,
// are those of evaluating the light's spectrum in the loop.
struct SampledLight {
    double kelvin;
    std::string illuminant;
    std::vector<double> power;  // at the table's wavelengths
    dvec3 lit;                  // max(sRGB(XYZ[I]), 0)
};

const SampledLight& sampled_light(const Light* light) {
    static const std::string none;
    const double kelvin = light ? light->temperature_k : 0.0;
    const std::string& illuminant = light ? light->illuminant : none;
    thread_local std::vector<SampledLight> cache;  // a scene has a few lights
    for (const SampledLight& s : cache)
        if (s.kelvin == kelvin && s.illuminant == illuminant) return s;
    if (cache.size() >= 16) cache.clear();  // no caller holds an entry across calls
    const spectral::Power power = spectral::light_power(kelvin, illuminant);
    const spectral::Observer& cmf = spectral::cie1931_observer();
    SampledLight s{kelvin, illuminant, {}, dvec3(0.0)};
    for (std::size_t i = 0; i < cmf.y.values.size(); ++i) {
        const double nm = cmf.y.start_nm + cmf.y.step_nm * double(i);
        s.power.push_back(power(nm));
        s.lit += s.power.back() * dvec3(cmf.x.values[i], cmf.y.values[i], cmf.z.values[i]);
    }
    s.lit = glm::max(spectral::linear_srgb(s.lit), dvec3(0.0));
    cache.push_back(std::move(s));
    return cache.back();
}

// Eq. 2 per wavelength over the CIE 1931 table, for the light and for what the
// surface of reflectance F reflects of it; C0 per channel as the ratio.
template <typename Reflectance>
dvec3 c0_of(const Light* light, Reflectance F) {
    const SampledLight& sampled = sampled_light(light);
    const spectral::Observer& cmf = spectral::cie1931_observer();
    dvec3 seen(0.0);
    for (std::size_t i = 0; i < cmf.y.values.size(); ++i) {
        const double nm = cmf.y.start_nm + cmf.y.step_nm * double(i);
        const dvec3 bar(cmf.x.values[i], cmf.y.values[i], cmf.z.values[i]);
        seen += F(nm) * sampled.power[i] * bar;
    }
    seen = glm::max(spectral::linear_srgb(seen), dvec3(0.0));
    dvec3 c0(0.0);
    for (int c = 0; c < 3; ++c)
        if (sampled.lit[c] > 0.0) c0[c] = seen[c] / sampled.lit[c];
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
