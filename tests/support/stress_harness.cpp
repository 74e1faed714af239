#include "stress_harness.h"

#include "gl/context.h"
#include "gl/program.h"
#include "passes/light_uniforms.h"
#include "gl/gl_object.h"
#include "passes/material_buffer.h"
#include "passes/material_texture.h"
#include "passes/render_targets.h"
#include "passes/shader_plan.h"
#include "models/model_spec.h"
#include "reference/reference.h"

#include <glm/geometric.hpp>

#include <stdexcept>
#include <string>

namespace m3055::test {

std::vector<Light> stress_lights(const StressBatch& batch) {
    Light light0 = batch.light0;
    light0.type = LightType::point;
    light0.position = dvec3(0.0);
    light0.att_constant = 1.0;
    light0.att_linear = 0.0;
    light0.att_quadratic = 0.0;
    light0.enabled = true;
    std::vector<Light> lights{light0};
    lights.insert(lights.end(), batch.more_lights.begin(), batch.more_lights.end());
    return lights;
}

Material float_rounded(Material material) {
    // Every parameter of the model (numbers, colours, directions, lobes); choices,
    // flags and lobe counts are small whole numbers, which float holds exactly.
    for (double& x : material.values()) x = double(float(x));
    return material;
}

struct StressHarness::Impl {
    std::unique_ptr<HeadlessContext> context = HeadlessContext::create(Backend::automatic);
    const GlApi& gl = context->gl();
    ProgramCache programs{gl};
    // The general program (every model, chosen per pixel at run time), as the renderer builds it.
    unsigned program = programs.get(
        {"passes/fullscreen.vert", "passes/stress.frag", specialization_defines(ShaderMode::general, {}, {})});
    GlVertexArray vao{gl};
    MaterialTexture materials{gl};
    GlTexture input_textures[3] = {GlTexture(gl), GlTexture(gl), GlTexture(gl)};  // N, V, P
    FloatTargets targets{gl, 2, false, "stress harness"};  // colour, transmittance

    std::vector<StressOutput> evaluate(const StressBatch& batch, int w) {
        const std::size_t count = batch.inputs.size();
        if (count == 0) return {};
        const int h = int((count + w - 1) / w);
        targets.ensure_size(w, h);

        // Inputs: raw N, raw V and P = -L_raw (see the header); padding pixels
        // get a harmless unit input and the first material.
        std::vector<float> texels[3];
        for (auto& t : texels) t.assign(std::size_t(w) * h * 4, 0.f);
        std::vector<float> records;
        records.reserve(std::size_t(w) * h * material_record_texels() * 4);
        for (std::size_t i = 0; i < std::size_t(w) * h; ++i) {
            const StressInput& in = batch.inputs[i < count ? i : 0];
            const glm::vec3 values[3] = {in.N, in.V, -in.L};
            for (int k = 0; k < 3; ++k)
                for (int c = 0; c < 3; ++c) texels[k][i * 4 + c] = values[k][c];
            pack_material(in.material, records);
        }
        for (int k = 0; k < 3; ++k) {
            gl.ActiveTexture(GL_TEXTURE1 + k);
            define_texture_2d(gl, input_textures[k], kRgba32f, w, h, texels[k].data());
        }
        materials.upload(records);

        gl.UseProgram(program);
        materials.set_uniforms(program);
        auto loc = [&](const char* name) { return gl.GetUniformLocation(program, name); };
        gl.Uniform1i(loc("u_normal"), 1);
        gl.Uniform1i(loc("u_view"), 2);
        gl.Uniform1i(loc("u_position"), 3);
        gl.Uniform1i(loc("u_width"), w);
        upload_lights(gl, program, pack_lights(stress_lights(batch)));

        gl.BindFramebuffer(GL_FRAMEBUFFER, targets.framebuffer());
        gl.Viewport(0, 0, w, h);
        gl.Disable(GL_DEPTH_TEST);
        gl.Disable(GL_BLEND);
        const float nan_fill[4] = {-1.f, -1.f, -1.f, -1.f};  // a pixel left unwritten shows as out of bounds
        gl.ClearBufferfv(GL_COLOR, 0, nan_fill);
        gl.ClearBufferfv(GL_COLOR, 1, nan_fill);
        gl.BindVertexArray(vao.id());
        gl.DrawArrays(GL_TRIANGLES, 0, 3);
        gl.BindVertexArray(0);
        const GLenum error = gl.GetError();
        if (error != GL_NO_ERROR) throw std::runtime_error("stress harness: GL error " + std::to_string(error));

        const std::vector<float> color = targets.read_rgba(0), transmittance = targets.read_rgba(1);
        gl.UseProgram(0);
        gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
        std::vector<StressOutput> out(count);
        for (std::size_t i = 0; i < count; ++i) {
            // Pixel i is row i / w counted from the bottom (gl_FragCoord's y), as the shader indexes it.
            for (int c = 0; c < 3; ++c) {
                out[i].color[c] = color[i * 4 + c];
                out[i].transmittance[c] = transmittance[i * 4 + c];
            }
        }
        return out;
    }
};

StressHarness::StressHarness() : impl_(std::make_unique<Impl>()) {}
StressHarness::~StressHarness() = default;

std::vector<StressOutput> StressHarness::evaluate_gpu(const StressBatch& batch, int width) {
    return impl_->evaluate(batch, width);
}

std::string StressHarness::renderer_string() const { return impl_->context->renderer_string(); }

StressOutput evaluate_reference(const StressInput& input, const std::vector<Light>& lights) {
    ref::SurfacePoint point;
    point.N = glm::normalize(dvec3(input.N));
    point.V = glm::normalize(dvec3(input.V));
    point.P = -dvec3(input.L);  // light 0 sits at the origin
    StressOutput out;
    if (is_translucent(input.material)) {
        const ref::TranslucentShade shade = ref::shade_translucent(input.material, lights, point);
        out.color = shade.color;
        out.transmittance = shade.transmittance;
    } else {
        out.color = ref::shade_opaque(input.material, lights, point);
    }
    return out;
}

}  // namespace m3055::test
