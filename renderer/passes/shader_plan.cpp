#include "passes/shader_plan.h"

#include "models/glsl_generator.h"
#include "models/model_table.h"
#include "scene/area_light.h"
#include "scene/conductor_use.h"

#include <set>

namespace m3055 {

std::vector<std::string> area_and_shadow_defines(const std::vector<Light>& lights) {
    bool area = false, shadows = false;
    for (const Light& light : lights) {
        if (!light.enabled || light.intensity <= 0.0) continue;  // dropped (passes/light_uniforms.cpp)
        area = area || is_area_light(light.type);
        shadows = shadows || light.shadow;
    }
    std::vector<std::string> defines;
    if (area) defines.push_back("HAS_AREA_LIGHTS");
    if (shadows) defines.push_back("HAS_SHADOWS");
    return defines;
}

std::vector<std::string> specialization_defines(ShaderMode mode, const std::vector<const Object*>& objects,
                                                const std::vector<Light>& lights) {
    if (mode == ShaderMode::general) {
        // Every model and light kind, chosen at run time (no SPECIALIZED, no LIGHT_COUNT);
        // area lights and shadows only where the scene has them (their code is large).
        std::vector<std::string> all = every_model_define(model_table());
        all.insert(all.end(), {"HAS_LIGHT_LOBES", "HAS_POINT_LIGHTS", "HAS_SPECTRAL_TABLES", "HAS_SPOT_LIGHTS"});
        const std::vector<std::string> extra = area_and_shadow_defines(lights);
        all.insert(all.end(), extra.begin(), extra.end());
        return all;
    }
    std::set<std::string> flags;  // sorted and unique: equal scenes give equal keys
    for (const Object* object : objects)
        for (const Material* material : materials_of(*object)) {
            const ModelSpec& model = material->model();
            flags.insert(has_define(model));
            flags.insert(family_define(static_cast<int>(model.family)));
            // The materials passes/spectral_tables.cpp gives a table.
            if (material->colour_spectrum() || conductor_use(*material)) flags.insert("HAS_SPECTRAL_TABLES");
        }
    int count = 0;
    for (const Light& light : lights) {
        if (!light.enabled || light.intensity <= 0.0) continue;  // dropped (passes/light_uniforms.cpp)
        ++count;
        if (light.type != LightType::directional) flags.insert("HAS_POINT_LIGHTS");
        if (light.type == LightType::spot) flags.insert("HAS_SPOT_LIGHTS");
        if (!light.lobes.empty()) flags.insert("HAS_LIGHT_LOBES");
    }
    for (const std::string& define : area_and_shadow_defines(lights)) flags.insert(define);
    std::vector<std::string> defines = {"SPECIALIZED", "LIGHT_COUNT " + std::to_string(count)};
    defines.insert(defines.end(), flags.begin(), flags.end());
    return defines;
}

}  // namespace m3055
