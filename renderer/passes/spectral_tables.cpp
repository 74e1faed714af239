#include "passes/spectral_tables.h"

#include "passes/light_uniforms.h"
#include "models/model_spec.h"
#include "passes/material_buffer.h"
#include "scene/conductor_use.h"
#include "scene/spectral_colour.h"
#include "spectral/conductor.h"
#include "spectral/reflected_colour.h"

#include <cstdio>
#include <map>
#include <optional>
#include <mutex>
#include <string>

namespace m3055 {

namespace {

// The spectrum a light stands for, as a key: "K3200", "IA", or "" (an RGB light: D65).
std::string spectrum_key(const Light& light) {
    if (light.temperature_k > 0.0) {
        char kelvin[32];
        std::snprintf(kelvin, sizeof kelvin, "K%.17g", light.temperature_k);
        return kelvin;
    }
    return light.illuminant.empty() ? std::string() : "I" + light.illuminant;
}

// C0 of `metal` under one spectrum at `samples` cosines in [0, 1] (1: normal incidence only).
std::vector<float> c0_over_cos(const spectral::ComplexIndex& metal, ConductorFresnel fresnel, const Light* light,
                               int samples) {
    const spectral::Power power =
        light ? spectral::light_power(light->temperature_k, light->illuminant) : spectral::light_power(0.0, "");
    std::vector<float> out;
    for (int s = 0; s < samples; ++s) {
        const double cos_theta = samples == 1 ? 1.0 : double(s) / double(samples - 1);
        const glm::dvec3 c0 = spectral::reflected_c0(
            power, [&](double nm) { return conductor_F(fresnel, metal.at(nm), cos_theta); });
        out.insert(out.end(), {float(c0.r), float(c0.g), float(c0.b), 0.0f});
    }
    return out;
}

// Kept per (metal, Fresnel, spectrum): a frame packs its records every time,
// and the tables change only when a light's spectrum or the metal does.
const std::vector<float>& cached_c0(const ConductorUse& use, int samples, const Light* light) {
    static std::mutex mutex;
    static std::map<std::string, std::vector<float>> cache;
    const std::string key = use.metal + "/" + std::to_string(int(use.fresnel)) + "/" + std::to_string(samples) +
                            "/" + (light ? spectrum_key(*light) : "");
    std::lock_guard<std::mutex> lock(mutex);
    auto found = cache.find(key);
    if (found != cache.end()) return found->second;
    if (cache.size() > 4096) cache.clear();  // bounded: an explorer session drags kelvin sliders
    return cache.emplace(key, c0_over_cos(spectral::conductor(use.metal), use.fresnel, light, samples))
        .first->second;
}

// The float of a record that holds its table's start: after the parameters, at
// the derived value "spectral_table" (models/builtin_models.cpp).
int table_float(const Material& material) {
    int k = 2 + int(material.values().size());
    for (const DerivedValue& value : material.model().derived) {
        if (value.name == "spectral_table") return k;
        k += value.floats;
    }
    return -1;
}

// A classic model's table (glsl/models/classic.glsl): texel 0 = (where kd's
// colours start, or -1; 0; 0; K, the conductor's texels a light, or 0), then
// the conductor's K texels a light (microfacet's ks), then kd_spectrum's one a light.
void append_classic_table(const Material& material, const std::vector<const Light*>& shaded,
                          std::vector<float>& records, std::size_t record_at) {
    const ReflectanceSpectrum* spectrum = material.colour_spectrum();
    const std::optional<ConductorUse> use = conductor_use(material);
    const int slot = table_float(material);
    if ((!spectrum && !use) || slot < 0) return;
    const int samples = !use ? 0 : use->fresnel == ConductorFresnel::normal ? 1 : spectral::kConductorCosSamples;
    const int kd_at = spectrum ? 1 + int(shaded.size()) * samples : -1;
    records[record_at + std::size_t(slot)] = float(records.size() / 4);
    records.insert(records.end(), {float(kd_at), 0.0f, 0.0f, float(samples)});
    if (use)
        for (const Light* light : shaded) {
            const std::vector<float>& table = cached_c0(*use, samples, light);
            records.insert(records.end(), table.begin(), table.end());
        }
    if (spectrum)
        for (const Light* light : shaded) {
            const dvec3 kd = spectrum_c0(*spectrum, light);
            records.insert(records.end(), {float(kd.r), float(kd.g), float(kd.b), 0.0f});
        }
}

}  // namespace

void append_spectral_tables(const std::vector<const Material*>& materials, const std::vector<Light>& lights,
                            std::vector<float>& records) {
    const std::size_t record_floats = std::size_t(material_record_texels()) * 4;
    std::vector<const Light*> shaded;
    for (const Light& light : lights)
        if (reaches_shader(light)) shaded.push_back(&light);
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const Material& material = *materials[i];
        const ReflectanceSpectrum* spectrum = material.colour_spectrum();
        if (material.model().family == Family::classic) {
            append_classic_table(material, shaded, records, i * record_floats);
            continue;
        }
        if (spectrum) {
            // A colour spectrum (docs/spec.md#73-spectral-colours): one C0 per light, the same at every angle.
            const int slot = table_float(material);
            if (slot < 0) continue;
            records[i * record_floats + std::size_t(slot)] = float(records.size() / 4);
            const dvec3 background = spectrum_c0(*spectrum, nullptr);
            records.insert(records.end(), {float(background.r), float(background.g), float(background.b), 1.0f});
            for (const Light* light : shaded) {
                const dvec3 c0 = spectrum_c0(*spectrum, light);
                records.insert(records.end(), {float(c0.r), float(c0.g), float(c0.b), 0.0f});
            }
            continue;
        }
        const std::optional<ConductorUse> use = conductor_use(material);
        const int slot = use ? table_float(material) : -1;
        if (slot < 0) continue;
        const int samples = use->fresnel == ConductorFresnel::normal ? 1 : spectral::kConductorCosSamples;
        records[i * record_floats + std::size_t(slot)] = float(records.size() / 4);
        // Texel 0: the background's C0 (D65, normal incidence) and, in alpha, K.
        std::vector<float> background = cached_c0({use->metal, ConductorFresnel::normal}, 1, nullptr);
        background[3] = float(samples);
        records.insert(records.end(), background.begin(), background.end());
        for (const Light* light : shaded) {
            const std::vector<float>& table = cached_c0(*use, samples, light);
            records.insert(records.end(), table.begin(), table.end());
        }
    }
}

}  // namespace m3055
