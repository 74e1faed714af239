#include "passes/brdf_grid.h"

#include "gl/gl_object.h"
#include "models/model_spec.h"
#include "passes/light_uniforms.h"
#include "passes/material_buffer.h"
#include "passes/material_texture.h"
#include "passes/render_targets.h"
#include "passes/shader_plan.h"

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace m3055 {

struct BrdfGrid::Impl {
    const GlApi& gl;
    std::unique_ptr<ProgramCache> own_programs;  // when no cache is shared
    // The programs by the model table's revision and the defines: a compile
    // costs tens of milliseconds on llvmpipe, and the explorer asks again for
    // every frame of a slider drag (the values are in the record).
    ProgramCache& programs;
    GlVertexArray vao;
    MaterialTexture material;
    GlTexture dirs[2];
    FloatTargets targets;  // colour (f) and transmittance, as the pass writes them

    Impl(const GlApi& api, std::unique_ptr<ProgramCache> own, ProgramCache* shared)
        : gl(api), own_programs(std::move(own)), programs(shared ? *shared : *own_programs), vao(api), material(api),
          dirs{GlTexture(api), GlTexture(api)}, targets(api, 2, false, "BRDF grid") {}

    void directions(int unit, const GlTexture& texture, const std::vector<dvec3>& list) {
        std::vector<float> rgba;
        for (const dvec3& d : list) rgba.insert(rgba.end(), {float(d.x), float(d.y), float(d.z), 0.f});
        gl.ActiveTexture(GL_TEXTURE0 + unit);
        define_texture_2d(gl, texture, kRgba32f, int(list.size()), 1, rgba.data());
    }
};

BrdfGrid::BrdfGrid(const GlApi& gl, ProgramCache& programs) : impl_(std::make_unique<Impl>(gl, nullptr, &programs)) {}
BrdfGrid::BrdfGrid(const GlApi& gl) : impl_(std::make_unique<Impl>(gl, std::make_unique<ProgramCache>(gl), nullptr)) {}
BrdfGrid::~BrdfGrid() = default;

namespace {

std::vector<std::string> grid_defines(const Material& material) {
    Object object;
    object.material = material;
    Light light;
    light.type = LightType::point;
    return specialization_defines(ShaderMode::specialized, {&object}, {light});
}

unsigned grid_program(ProgramCache& programs, const Material& material) {
    return programs.get({"passes/fullscreen.vert", "passes/brdf_grid.frag", grid_defines(material)});
}

// One draw of the grid with light 0 of colour `white`: RGB per (L, V). (Black,
// not intensity 0: a light of intensity 0 is dropped from the uniforms.)
std::vector<float> draw(const GlApi& gl, unsigned program, const FloatTargets& targets, double white, unsigned vao) {
    const int w = targets.width(), h = targets.height();
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
    const std::vector<float> rgba = targets.read_rgba(0);
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
    const unsigned program = grid_program(impl_->programs, material);
    impl_->targets.ensure_size(w, h);
    std::vector<float> record;
    pack_material(without_ambient_term(material), record);
    impl_->material.upload(record);
    impl_->directions(1, impl_->dirs[0], Ls);
    impl_->directions(2, impl_->dirs[1], Vs);
    gl.UseProgram(program);
    impl_->material.set_uniforms(program);
    auto loc = [&](const char* name) { return gl.GetUniformLocation(program, name); };
    gl.Uniform1i(loc("u_dirs_l"), 1);
    gl.Uniform1i(loc("u_dirs_v"), 2);
    gl.Uniform1i(loc("u_paired"), paired ? 1 : 0);
    std::vector<float> f = draw(gl, program, impl_->targets, 1.0, impl_->vao.id());
    // The highlight model adds a light-independent term (d C0, eq. 3): the BRDF
    // is what the light adds, so that term (drawn with the light off) goes.
    // (The metals' d is set to 0 instead: see without_ambient_term.)
    if (material.model().family == Family::opaque) {
        const std::vector<float> base = draw(gl, program, impl_->targets, 0.0, impl_->vao.id());
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

std::string brdf_compile_error(ProgramCache& programs, const Material& material) {
    try {
        grid_program(programs, material);
    } catch (const ShaderError& e) {
        return e.what();
    }
    return "";
}

std::string brdf_compile_error(const GlApi& gl, const Material& material) {
    ProgramCache programs(gl);
    return brdf_compile_error(programs, material);
}

}  // namespace m3055
