// The lights as glsl/common/lights.glsl reads them. Disabled and zero-intensity
// lights are dropped here: they contribute nothing to any model.
#pragma once

#include "gl/gl_api.h"
#include "scene/scene.h"

#include <vector>

namespace m3055 {

struct LightUniforms {
    int count = 0;
    std::vector<float> vector, scale, spot, att, lobes;  // vec4, vec3, vec4, vec3, 2 x vec4 per light
    std::vector<int> lobe_count, lobe_kind;
};

LightUniforms pack_lights(const std::vector<Light>& lights);

// Sets the u_light_* uniforms of the program in use.
void upload_lights(const GlApi& gl, unsigned program, const LightUniforms& lights);

}  // namespace m3055
