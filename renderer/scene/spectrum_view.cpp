#include "scene/spectrum_view.h"

#include "models/model_spec.h"
#include "scene/conductor_use.h"
#include "spectral/conductor.h"
#include "spectral/reflected_colour.h"

#include <cmath>
#include <cstdio>

namespace m3055 {

namespace {

std::string light_label(const Light* light) {
    if (!light) return "D65 (no light: the display's white)";
    if (light->temperature_k > 0.0) {
        char text[64];
        std::snprintf(text, sizeof text, "black body %.0f K", light->temperature_k);
        return text;
    }
    if (!light->illuminant.empty()) return "CIE illuminant " + light->illuminant;
    // docs/spec.md#72-measured-metals: an RGB light stands for D65 scaled per channel by its colour.
    char text[128];
    std::snprintf(text, sizeof text, "D65 (an RGB light: its colour %.3g %.3g %.3g scales the channels)",
                  light->color.r, light->color.g, light->color.b);
    return text;
}

}  // namespace

SpectrumView spectrum_view(const Light* light, const Material* material) {
    SpectrumView view;
    view.light_label = light_label(light);
    const spectral::Power power =
        light ? spectral::light_power(light->temperature_k, light->illuminant) : spectral::light_power(0.0, "");
    spectral::Power reflectance;
    if (!material) {
        view.no_reflectance = "no material";
    } else if (const ReflectanceSpectrum* spectrum = material->colour_spectrum()) {
        reflectance = [spectrum](double nm) { return spectrum->at(nm); };
        view.reflectance_label = "color_spectrum";  // the paper's models; the classic ones name it kd_spectrum
        for (const ParamSpec& param : material->model().params)
            if (!param.spectrum_key.empty()) view.reflectance_label = param.spectrum_key;
    } else if (const std::optional<ConductorUse> use = conductor_use(*material)) {
        const spectral::ComplexIndex* metal = &spectral::conductor(use->metal);
        // The paper's R(lambda) = F(lambda, 0) (assumption 3); "full" and Schlick depart from it off normal.
        reflectance = [metal](double nm) { return spectral::normal_reflectance(metal->at(nm)); };
        view.reflectance_label = use->metal + ", R(lambda) at normal incidence";
    } else {
        view.no_reflectance = "model " + material->shown_name() + ": an RGB colour, no spectrum";
    }
    view.curves = spectral::spectrum_curves(power, reflectance ? &reflectance : nullptr);
    if (light) view.light_colour = light->color;
    if (reflectance) view.reflectance_colour = spectral::reflected_c0(spectral::light_power(0.0, ""), reflectance);
    return view;
}

}  // namespace m3055
