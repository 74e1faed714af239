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
    std::vector<float> ambient;                  // vec3 per light: a_l ambient_l (classic models)
    float global_ambient[3] = {0.0f, 0.0f, 0.0f};  // the scene's L_glob (classic models)
};

// Whether a light reaches the shader: enabled with a positive intensity. The
// shader's light i is the i-th such light of the scene.
inline bool reaches_shader(const Light& light) { return light.enabled && light.intensity > 0.0; }

// `global_ambient` is Scene::ambient (the lecture's L_glob).
LightUniforms pack_lights(const std::vector<Light>& lights, const dvec3& global_ambient = dvec3(0.0));

// Sets the u_light_* uniforms of the program in use.
void upload_lights(const GlApi& gl, unsigned program, const LightUniforms& lights);

}  // namespace m3055
