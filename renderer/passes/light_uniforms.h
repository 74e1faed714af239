// The lights as glsl/common/lights.glsl reads them. Disabled and zero-intensity
// lights are dropped here: they contribute nothing to any model.
#pragma once

#include "gl/gl_api.h"
#include "scene/scene.h"

#include <optional>
#include <string>
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

// The first light the shaders cannot draw yet, as "lights[2].type: rect lights
// are not drawn by this build yet" (rect, disk and sky lights) or "lights[0].shadow:
// shadows are not drawn by this build yet", or nothing. The CPU reference draws
// them (docs/spec.md#75-area-lights-the-sky-and-shadows); Renderer::render refuses
// them rather than drawing something else.
std::optional<std::string> undrawn_light(const std::vector<Light>& lights);

// `global_ambient` is Scene::ambient (the lecture's L_glob). Throws
// std::logic_error for a light undrawn_light names.
LightUniforms pack_lights(const std::vector<Light>& lights, const dvec3& global_ambient = dvec3(0.0));

// Sets the u_light_* uniforms of the program in use.
void upload_lights(const GlApi& gl, unsigned program, const LightUniforms& lights);

}  // namespace m3055
