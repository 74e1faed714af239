#include "passes/light_uniforms.h"

#include "scene/area_light.h"

#include <stdexcept>

namespace m3055 {

std::optional<std::string> undrawn_light(const std::vector<Light>& lights) {
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const std::string path = "lights[" + std::to_string(i) + "]";
        if (is_area_light(lights[i].type))
            return path + ".type: " + to_string(lights[i].type) + " lights are not drawn by this build yet";
        if (lights[i].shadow) return path + ".shadow: shadows are not drawn by this build yet";
    }
    return std::nullopt;
}

LightUniforms pack_lights(const std::vector<Light>& lights, const dvec3& global_ambient) {
    LightUniforms u;
    for (int c = 0; c < 3; ++c) u.global_ambient[c] = float(global_ambient[c]);
    if (const auto problem = undrawn_light(lights)) throw std::logic_error(*problem);
    for (const auto& light : lights) {
        if (!reaches_shader(light)) continue;
        const dvec3 scale = light.intensity * light.color;
        const dvec3 where = light.type == LightType::directional ? light.direction : light.position;
        const float type = light.type == LightType::directional ? 0.f : light.type == LightType::point ? 1.f : 2.f;
        u.vector.insert(u.vector.end(), {float(where.x), float(where.y), float(where.z), type});
        u.scale.insert(u.scale.end(), {float(scale.r), float(scale.g), float(scale.b)});
        u.spot.insert(u.spot.end(), {float(light.spot_direction.x), float(light.spot_direction.y),
                                     float(light.spot_direction.z), float(light.spot_exponent)});
        u.att.insert(u.att.end(), {float(light.att_constant), float(light.att_linear), float(light.att_quadratic)});
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
}

}  // namespace m3055
