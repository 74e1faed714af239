#include "passes/light_uniforms.h"

#include "geometry/mesh.h"
#include "scene/area_light.h"

#include <algorithm>
#include <stdexcept>

namespace m3055 {

int shader_type(LightType type) {
    switch (type) {
        case LightType::directional: return 0;
        case LightType::point: return 1;
        case LightType::spot: return 2;
        case LightType::rect: return 3;
        case LightType::disk: return 4;
        case LightType::sky: return 5;
    }
    return 0;
}

LightUniforms pack_lights(const std::vector<Light>& lights, const dvec3& global_ambient, AreaSampling sampling) {
    LightUniforms u;
    for (int c = 0; c < 3; ++c) u.global_ambient[c] = float(global_ambient[c]);
    u.sampling = sampling;
    for (const auto& light : lights) {
        if (!reaches_shader(light)) continue;
        const float type = float(shader_type(light.type));
        // An area light's scale is its radiance, its vector the emitter's centre (the sky's: up), its
        // spot direction the emitter's normal, and its extent the emitter's half-sides or radius axes.
        const bool area = is_area_light(light.type);
        const dvec3 scale = area ? radiance(light) : light.intensity * light.color;
        const dvec3 where = light.type == LightType::directional ? light.direction
                            : light.type == LightType::sky       ? light.up
                                                                 : light.position;
        const dvec3 facing = area ? light.normal : light.spot_direction;
        u.vector.insert(u.vector.end(), {float(where.x), float(where.y), float(where.z), type});
        u.scale.insert(u.scale.end(), {float(scale.r), float(scale.g), float(scale.b)});
        u.spot.insert(u.spot.end(), {float(facing.x), float(facing.y), float(facing.z), float(light.spot_exponent)});
        u.att.insert(u.att.end(), {float(light.att_constant), float(light.att_linear), float(light.att_quadratic)});
        dvec3 e0(0.0), e1(0.0);
        if (light.type == LightType::rect) {
            const RectFrame frame = rect_frame(light);
            e0 = 0.5 * light.size[0] * frame.side0;
            e1 = 0.5 * light.size[1] * frame.side1;
        } else if (light.type == LightType::disk) {
            const geometry::AxisFrame frame = geometry::axis_frame(light.normal);
            e0 = light.radius * frame.t;
            e1 = light.radius * frame.b;
        }
        u.extent.insert(u.extent.end(), {float(e0.x), float(e0.y), float(e0.z), 0.f, float(e1.x), float(e1.y),
                                         float(e1.z), 0.f});
        u.shadow.push_back(light.shadow ? 1 : 0);
        u.any_area = u.any_area || area;
        u.any_shadow = u.any_shadow || light.shadow;
        const std::size_t samples = area ? std::size_t(2 * sampling.light * sampling.light) : 1;
        // An area light's shadow: a rect's or disk's probe, then in a penumbra (the sky: always) a ray a sample.
        const std::size_t side = std::size_t(std::min(sampling.shadow, 3));
        const std::size_t probe = light.type == LightType::sky ? 0 : side * side;
        const std::size_t rays = !light.shadow ? 0 : !area || sampling.light <= 1 ? 1 : probe + samples;
        // The sky takes twice the strata a side, untraced, under a lobe no closed form makes
        // exact (glsl/common/lights.glsl: area_side); counted so whatever the materials.
        const std::size_t untraced = light.type == LightType::sky && sampling.light > 1 ? 3 * samples : 0;
        u.work += samples + untraced + 10 * rays;
        float lobes[8] = {0, 0, 0, 0, 0, 0, 0, 0};
        for (std::size_t j = 0; j < light.lobes.size() && j < 4; ++j) {
            lobes[2 * j] = float(light.lobes[j].w);
            lobes[2 * j + 1] = float(light.lobes[j].m);
        }
        u.lobes.insert(u.lobes.end(), lobes, lobes + 8);
        u.lobe_count.push_back(int(light.lobes.size()));
        u.lobe_kind.push_back(light.lobe_kind == LobeKind::beckmann ? 0 : 1);
        const dvec3 ambient = light.intensity * light.ambient;
        u.ambient.insert(u.ambient.end(), {float(ambient.r), float(ambient.g), float(ambient.b)});
        ++u.count;
    }
    return u;
}

void upload_lights(const GlApi& gl, unsigned program, const LightUniforms& lights) {
    auto location = [&](const char* name) { return gl.GetUniformLocation(program, name); };
    gl.Uniform1i(location("u_light_count"), lights.count);
    gl.Uniform3fv(location("u_global_ambient"), 1, lights.global_ambient);  // -1 (no-op) unless classic
    if (lights.count == 0) return;
    gl.Uniform3fv(location("u_light_ambient"), lights.count, lights.ambient.data());
    gl.Uniform4fv(location("u_light_vector"), lights.count, lights.vector.data());
    gl.Uniform3fv(location("u_light_scale"), lights.count, lights.scale.data());
    gl.Uniform4fv(location("u_light_spot"), lights.count, lights.spot.data());
    gl.Uniform3fv(location("u_light_att"), lights.count, lights.att.data());
    gl.Uniform1iv(location("u_light_lobe_count"), lights.count, lights.lobe_count.data());
    gl.Uniform1iv(location("u_light_lobe_kind"), lights.count, lights.lobe_kind.data());
    gl.Uniform4fv(location("u_light_lobes"), lights.count * 2, lights.lobes.data());
    // Only in programs with area lights or shadows (-1 elsewhere: no-ops).
    gl.Uniform4fv(location("u_light_extent"), lights.count * 2, lights.extent.data());
    gl.Uniform1iv(location("u_light_shadow"), lights.count, lights.shadow.data());
    gl.Uniform1i(location("u_area_samples"), lights.sampling.light);
    gl.Uniform1i(location("u_shadow_samples"), lights.sampling.shadow);
}

}  // namespace m3055
