#include "scene/light_colour.h"

#include "spectral/blackbody.h"
#include "spectral/cie_data.h"
#include "spectral/colorimetry.h"

#include <glm/common.hpp>

#include <algorithm>

namespace m3055 {

static_assert(kMinLightKelvin == spectral::kMinKelvin && kMaxLightKelvin == spectral::kMaxKelvin);

LightColourSource colour_source(const Light& light) {
    if (light.temperature_k > 0.0) return LightColourSource::temperature;
    if (!light.illuminant.empty()) return LightColourSource::illuminant;
    return LightColourSource::rgb;
}

void set_rgb_colour(Light& light, const dvec3& rgb) {
    light.color = glm::clamp(rgb, dvec3(0.0), dvec3(1.0));
    light.temperature_k = 0.0;
    light.illuminant.clear();
}

bool set_temperature(Light& light, double kelvin, std::string* error) {
    const double k = std::clamp(kelvin, kMinLightKelvin, kMaxLightKelvin);
    try {
        const dvec3 rgb = spectral::temperature_rgb(k);
        light.color = rgb;
        light.temperature_k = k;
        light.illuminant.clear();
        return true;
    } catch (const spectral::SpectralError& e) {
        if (error) *error = e.what();
        return false;
    }
}

bool set_illuminant(Light& light, const std::string& name, std::string* error) {
    const auto& names = spectral::illuminant_names();
    if (std::find(names.begin(), names.end(), name) == names.end()) {
        if (error) *error = "\"" + name + "\" is not a CIE illuminant colord-data has";
        return false;
    }
    try {
        const dvec3 rgb = spectral::illuminant_rgb(name);
        light.color = rgb;
        light.illuminant = name;
        light.temperature_k = 0.0;
        return true;
    } catch (const spectral::SpectralError& e) {
        if (error) *error = e.what();
        return false;
    }
}

const std::vector<std::string>& light_illuminant_names() { return spectral::illuminant_names(); }

}  // namespace m3055
