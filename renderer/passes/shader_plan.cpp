#include "passes/shader_plan.h"

#include "models/glsl_generator.h"
#include "models/model_table.h"

#include <set>

namespace m3055 {

std::vector<std::string> specialization_defines(ShaderMode mode, const std::vector<const Object*>& objects,
                                                const std::vector<Light>& lights) {
    if (mode == ShaderMode::general) {
        // Every model and light kind, chosen at run time (no SPECIALIZED, no LIGHT_COUNT).
        std::vector<std::string> all = every_model_define(model_table());
        all.insert(all.end(), {"HAS_LIGHT_LOBES", "HAS_POINT_LIGHTS", "HAS_SPOT_LIGHTS"});
        return all;
    }
    std::set<std::string> flags;  // sorted and unique: equal scenes give equal keys
    for (const Object* object : objects)
        for (const Material* material : materials_of(*object)) {
            const ModelSpec& model = material->model();
            flags.insert(has_define(model));
            flags.insert(family_define(static_cast<int>(model.family)));
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
