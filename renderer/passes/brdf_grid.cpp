#include "passes/brdf_grid.h"

#include "gl/program.h"
#include "passes/light_uniforms.h"
#include "passes/material_buffer.h"
#include "models/model_spec.h"
#include "models/model_table.h"
#include "passes/shader_plan.h"

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace m3055 {

struct BrdfGrid::Impl {
    const GlApi& gl;
    unsigned vao = 0, material_buffer = 0, material_texture = 0, dirs[2] = {0, 0}, targets[2] = {0, 0}, fbo = 0;
    // The programs built so far, by the model table's revision and the defines:
    // a compile costs tens of milliseconds on llvmpipe, and the explorer asks
    // again for every frame of a slider drag (the values are in the record).
    std::map<std::pair<std::uint64_t, std::vector<std::string>>, unsigned> programs;

    explicit Impl(const GlApi& api) : gl(api) {
        gl.GenVertexArrays(1, &vao);
        gl.GenBuffers(1, &material_buffer);
        gl.GenTextures(1, &material_texture);
        gl.GenTextures(2, dirs);
        gl.GenTextures(2, targets);
        gl.GenFramebuffers(1, &fbo);
    }
    ~Impl() {
        for (const auto& entry : programs) gl.DeleteProgram(entry.second);
        gl.DeleteFramebuffers(1, &fbo);
        gl.DeleteTextures(2, targets);
        gl.DeleteTextures(2, dirs);
        gl.DeleteTextures(1, &material_texture);
        gl.DeleteBuffers(1, &material_buffer);
        gl.DeleteVertexArrays(1, &vao);
    }

    void texture(unsigned id, int w, int h, const float* rgba) {
        gl.BindTexture(GL_TEXTURE_2D, id);
        gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, rgba);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }

    void directions(int unit, unsigned id, const std::vector<dvec3>& list) {
        std::vector<float> rgba;
        for (const dvec3& d : list) rgba.insert(rgba.end(), {float(d.x), float(d.y), float(d.z), 0.f});
        gl.ActiveTexture(GL_TEXTURE0 + unit);
        texture(id, int(list.size()), 1, rgba.data());
    }

    void material(const Material& m) {
        std::vector<float> record;
        pack_material(m, record);
        gl.BindBuffer(GL_TEXTURE_BUFFER, material_buffer);
        gl.BufferData(GL_TEXTURE_BUFFER, GLsizeiptr(record.size() * sizeof(float)), record.data(), GL_STREAM_DRAW);
        gl.ActiveTexture(GL_TEXTURE0);
        gl.BindTexture(GL_TEXTURE_BUFFER, material_texture);
        gl.TexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, material_buffer);
    }

    void targets_of(int w, int h) {
        gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
        for (int i = 0; i < 2; ++i) {
            texture(targets[i], w, h, nullptr);
            gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + i, GL_TEXTURE_2D, targets[i], 0);
        }
        const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        gl.DrawBuffers(2, buffers);
        if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw std::runtime_error("BRDF grid: incomplete RGBA32F framebuffer " + std::to_string(w) + "x" +
                                     std::to_string(h));
    }
};

BrdfGrid::BrdfGrid(const GlApi& gl) : impl_(std::make_unique<Impl>(gl)) {}
BrdfGrid::~BrdfGrid() = default;

namespace {

std::vector<std::string> grid_defines(const Material& material) {
    Object object;
    object.material = material;
    Light light;
    light.type = LightType::point;
    return specialization_defines(ShaderMode::specialized, {&object}, {light});
}

unsigned grid_program(const GlApi& gl, const Material& material) {
    return build_program(gl, {"passes/fullscreen.vert", "passes/brdf_grid.frag", grid_defines(material)});
}

// One draw of the grid with light 0 of colour `white`: RGB per (L, V). (Black,
// not intensity 0: a light of intensity 0 is dropped from the uniforms.)
std::vector<float> draw(const GlApi& gl, unsigned program, int w, int h, double white, unsigned vao) {
    Light light;  // a point light at the origin, attenuation 1: the pixel sits at -L
    light.type = LightType::point;
    light.position = dvec3(0.0);
    light.color = dvec3(white);
    upload_lights(gl, program, pack_lights({light}));
    gl.Viewport(0, 0, w, h);
    gl.Disable(GL_DEPTH_TEST);
    gl.Disable(GL_BLEND);
    // The renderer's translucent pass leaves a dual-source blend function
    // (GL_SRC1_COLOR); with it set, Mesa refuses a draw into our two colour
    // buffers even with blending off (GL_INVALID_OPERATION), so reset it.
    gl.BlendFunc(GL_ONE, GL_ZERO);
    gl.BindVertexArray(vao);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    gl.BindVertexArray(0);
    std::vector<float> rgba(std::size_t(w) * std::size_t(h) * 4);
    gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
    gl.ReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, rgba.data());
    std::vector<float> rgb(std::size_t(w) * std::size_t(h) * 3);
    for (std::size_t i = 0; i < std::size_t(w) * std::size_t(h); ++i)
        for (std::size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = rgba[i * 4 + c];
    return rgb;
}

// The metals' d C0 (eq. 12, 15, 16) is a pure sum term, so the light's share
// is exactly the model with d = 0. Subtracting a light-off draw instead left
// float cancellation noise where d/(pi N.L) dwarfs the lobe (grazing L), which
// read as a 3.9 % reciprocity error of eq. 12.
Material without_ambient_term(const Material& material) {
    if (material.model().family != Family::metal) return material;
    Material light_only = material;
    light_only.set_number("d", 0.0);
    return light_only;
}

}  // namespace

std::vector<float> BrdfGrid::evaluate(const Material& material, const std::vector<dvec3>& Ls,
                                      const std::vector<dvec3>& Vs) {
    return run(material, Ls, Vs, false);
}

std::vector<float> BrdfGrid::evaluate_pairs(const Material& material, const std::vector<dvec3>& Ls,
                                            const std::vector<dvec3>& Vs) {
    if (Ls.size() != Vs.size()) throw std::invalid_argument("BRDF grid: as many L as V for pairs");
    return run(material, Ls, Vs, true);
}

std::vector<float> BrdfGrid::run(const Material& material, const std::vector<dvec3>& Ls, const std::vector<dvec3>& Vs,
                                 bool paired) {
    const GlApi& gl = impl_->gl;
    const int w = int(Ls.size()), h = paired ? 1 : int(Vs.size());
    if (w < 1 || h < 1 || w > 16384 || h > 16384) throw std::invalid_argument("BRDF grid: 1 to 16384 L and V");
    auto key = std::make_pair(model_table().revision(), grid_defines(material));
    auto cached = impl_->programs.find(key);
    if (cached == impl_->programs.end())
        cached = impl_->programs.emplace(std::move(key), grid_program(gl, material)).first;
    const unsigned program = cached->second;
    impl_->targets_of(w, h);
    impl_->material(without_ambient_term(material));
    impl_->directions(1, impl_->dirs[0], Ls);
    impl_->directions(2, impl_->dirs[1], Vs);
    gl.UseProgram(program);
    auto loc = [&](const char* name) { return gl.GetUniformLocation(program, name); };
    gl.Uniform1i(loc("u_materials"), 0);
    gl.Uniform1i(loc("u_material_texels"), material_record_texels());
    gl.Uniform1i(loc("u_dirs_l"), 1);
    gl.Uniform1i(loc("u_dirs_v"), 2);
    gl.Uniform1i(loc("u_paired"), paired ? 1 : 0);
    std::vector<float> f = draw(gl, program, w, h, 1.0, impl_->vao);
    // The highlight model adds a light-independent term (d C0, eq. 3): the BRDF
    // is what the light adds, so that term (drawn with the light off) goes.
    // (The metals' d is set to 0 instead: see without_ambient_term.)
    if (material.model().family == Family::opaque) {
        const std::vector<float> base = draw(gl, program, w, h, 0.0, impl_->vao);
        for (std::size_t i = 0; i < f.size(); ++i) {
            const float NoL = float(Ls[(i / 3) % std::size_t(w)].z);
            if (NoL > 0.f) f[i] -= base[i];
        }
    }
    gl.UseProgram(0);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    const GLenum error = gl.GetError();
    if (error != GL_NO_ERROR) throw std::runtime_error("BRDF grid: GL error " + std::to_string(error));
    return f;
}

std::string brdf_compile_error(const GlApi& gl, const Material& material) {
    try {
        gl.DeleteProgram(grid_program(gl, material));
    } catch (const ShaderError& e) {
        return e.what();
    }
    return "";
}

}  // namespace m3055
