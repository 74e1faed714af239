// The lights as glsl/common/lights.glsl reads them. Disabled and zero-intensity
// lights are dropped here: they contribute nothing to any model.
#pragma once

#include "gl/gl_api.h"
#include "scene/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace m3055 {

// How an area or sky light is sampled (glsl/common/area_lights.glsl): n x n
// samples of the emitter (and as many of the model's highlight) for the
// shading (`light`), and, with a shadow, a rect or disk probed with m x m rays
// (`shadow`, at most 3 x 3), then in a penumbra (the sky: always) one ray for
// each of the samples. The render's
// setting and its error against the reference: docs/lights.md. The explorer's
// preview while a slider moves takes one point of each emitter (n = 1: exact
// for Lambert terms), two for the paper's highlight and Phong (exact for them
// with the lobe's closed form), and one ray to the centre (a hard shadow).
struct AreaSampling {
    int light = 8;
    int shadow = 3;
    // A highlight of whole exponent under a rect or the sky integrated exactly
    // (glsl/common/lobe_moment.glsl, compiled in only then: kLobeClosedFormDefine);
    // off: the samples scaled by E / E_s alone. On in the render and the preview
    // (one program for both in the explorer; its compile costs about 3-5 s more
    // on llvmpipe, once per scene shape; docs/lights.md).
    bool lobe_closed_form = false;
    bool operator==(const AreaSampling& o) const {
        return light == o.light && shadow == o.shadow && lobe_closed_form == o.lobe_closed_form;
    }
    bool operator!=(const AreaSampling& o) const { return !(*this == o); }
};
inline constexpr AreaSampling kRenderSampling{8, 3, true};
// The define of the programs that integrate the lobe in closed form (AreaSampling::lobe_closed_form).
inline constexpr const char* kLobeClosedFormDefine = "HAS_LOBE_CLOSED_FORM";
inline constexpr AreaSampling kFastSampling{1, 1, true};

struct LightUniforms {
    int count = 0;
    std::vector<float> vector, scale, spot, att, lobes;  // vec4, vec3, vec4, vec3, 2 x vec4 per light
    std::vector<float> extent;                   // 2 x vec4 per light: an area light's half-sides or radius axes
    std::vector<int> shadow;                     // 1 where the light casts shadows
    AreaSampling sampling = kRenderSampling;
    bool any_area = false, any_shadow = false;
    // The lights' shading work in plain lights (passes/draw_chunks.h's pixel-lights): an
    // area light's samples one each, a shadow ray about ten.
    std::size_t work = 0;
    std::vector<int> lobe_count, lobe_kind;
    std::vector<float> ambient;                  // vec3 per light: a_l ambient_l (classic models)
    float global_ambient[3] = {0.0f, 0.0f, 0.0f};  // the scene's L_glob (classic models)
};

// Whether a light reaches the shader: enabled with a positive intensity. The
// shader's light i is the i-th such light of the scene.
inline bool reaches_shader(const Light& light) { return light.enabled && light.intensity > 0.0; }

// The type code of glsl/common/lights.glsl (LIGHT_DIRECTIONAL ... LIGHT_SKY).
int shader_type(LightType type);

// `global_ambient` is Scene::ambient (the lecture's L_glob).
LightUniforms pack_lights(const std::vector<Light>& lights, const dvec3& global_ambient = dvec3(0.0),
                          AreaSampling sampling = kRenderSampling);

// Sets the u_light_* uniforms of the program in use.
void upload_lights(const GlApi& gl, unsigned program, const LightUniforms& lights);

}  // namespace m3055
