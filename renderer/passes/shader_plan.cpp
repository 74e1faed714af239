#include "passes/shader_plan.h"

#include <set>

namespace m3055 {

std::vector<std::string> specialization_defines(ShaderMode mode, const std::vector<const Object*>& objects,
                                                const std::vector<Light>& lights) {
    if (mode == ShaderMode::general) return {};
    std::set<std::string> flags;  // sorted and unique: equal scenes give equal keys
    for (const Object* object : objects) {
        switch (object->material.model) {
            case Model::highlight: flags.insert("HAS_HIGHLIGHT"); break;
            case Model::translucent: break;  // the translucent pass's own program
            case Model::metal: flags.insert("HAS_METAL"); break;
            case Model::metal_blinn: flags.insert("HAS_METAL_BLINN"); break;
            case Model::metal_phong: flags.insert("HAS_METAL_PHONG"); break;
            case Model::lambert: flags.insert("HAS_LAMBERT"); break;
            case Model::half_lambert: flags.insert("HAS_HALF_LAMBERT"); break;
            case Model::half_lambert_clamped: flags.insert("HAS_HALF_LAMBERT_CLAMPED"); break;
            case Model::half_lambert_normalized: flags.insert("HAS_HALF_LAMBERT_NORMALIZED"); break;
            case Model::oren_nayar: flags.insert("HAS_OREN_NAYAR"); break;
            case Model::phong: flags.insert("HAS_PHONG"); break;
            case Model::blinn_phong: flags.insert("HAS_BLINN_PHONG"); break;
            case Model::microfacet: flags.insert("HAS_MICROFACET"); break;
            case Model::ward: flags.insert("HAS_WARD"); break;
            case Model::heidrich_seidel: flags.insert("HAS_HEIDRICH_SEIDEL"); break;
        }
    }
    int count = 0;
    for (const Light& light : lights) {
        if (!light.enabled || light.intensity <= 0.0) continue;  // dropped (passes/light_uniforms.cpp)
        ++count;
        if (light.type != LightType::directional) flags.insert("HAS_POINT_LIGHTS");
        if (light.type == LightType::spot) flags.insert("HAS_SPOT_LIGHTS");
        if (!light.lobes.empty()) flags.insert("HAS_LIGHT_LOBES");
    }
    std::vector<std::string> defines = {"SPECIALIZED", "LIGHT_COUNT " + std::to_string(count)};
    defines.insert(defines.end(), flags.begin(), flags.end());
    return defines;
}

}  // namespace m3055
