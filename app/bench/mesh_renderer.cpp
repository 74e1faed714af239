#include "mesh_renderer.h"

#include "uv_sphere.h"
#include "passes/camera_frame.h"
#include "passes/camera_uniforms.h"
#include "passes/light_uniforms.h"
#include "passes/material_buffer.h"

#include <stdexcept>

namespace m3055::bench {

MeshRenderer::MeshRenderer(const GlApi& gl) : gl_(gl), programs_(gl) {
    gl_.GenVertexArrays(1, &vao_);
    gl_.GenVertexArrays(1, &empty_vao_);
    gl_.GenBuffers(1, &vertex_buffer_);
    gl_.GenBuffers(1, &index_buffer_);
    gl_.GenBuffers(1, &material_buffer_);
    gl_.GenTextures(1, &material_texture_);
    gl_.BindVertexArray(vao_);
    gl_.BindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    gl_.EnableVertexAttribArray(0);
    gl_.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_);  // recorded in the VAO
    gl_.BindVertexArray(0);
}

MeshRenderer::~MeshRenderer() {
    release_targets();
    gl_.DeleteVertexArrays(1, &vao_);
    gl_.DeleteVertexArrays(1, &empty_vao_);
    unsigned buffers[] = {vertex_buffer_, index_buffer_, material_buffer_};
    gl_.DeleteBuffers(3, buffers);
    gl_.DeleteTextures(1, &material_texture_);
}

void MeshRenderer::set_tessellation(int slices, int stacks) {
    const UvSphere mesh = make_uv_sphere(slices, stacks);
    gl_.BindVertexArray(vao_);
    gl_.BindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    gl_.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.positions.size() * sizeof(float)), mesh.positions.data(),
                   GL_STATIC_DRAW);
    gl_.BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)),
                   mesh.indices.data(), GL_STATIC_DRAW);
    gl_.BindVertexArray(0);
    index_count_ = int(mesh.indices.size());
}

void MeshRenderer::release_targets() {
    if (!scene_fbo_) return;
    gl_.DeleteFramebuffers(1, &scene_fbo_);
    gl_.DeleteFramebuffers(1, &display_fbo_);
    unsigned textures[] = {colour_, depth_, display_};
    gl_.DeleteTextures(3, textures);
    scene_fbo_ = display_fbo_ = 0;
}

void MeshRenderer::ensure_targets(int w, int h) {
    if (scene_fbo_ && w == width_ && h == height_) return;
    release_targets();
    width_ = w, height_ = h;
    auto texture = [&](GLint internal_format, GLenum format, GLenum type) {
        unsigned t = 0;
        gl_.GenTextures(1, &t);
        gl_.BindTexture(GL_TEXTURE_2D, t);
        gl_.TexImage2D(GL_TEXTURE_2D, 0, internal_format, w, h, 0, format, type, nullptr);
        gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        return t;
    };
    // The same formats as the Renderer's targets (renderer/renderer.cpp).
    colour_ = texture(GL_RGBA32F, GL_RGBA, GL_FLOAT);
    depth_ = texture(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT);
    display_ = texture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE);
    gl_.GenFramebuffers(1, &scene_fbo_);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, scene_fbo_);
    gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_, 0);
    gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_, 0);
    gl_.GenFramebuffers(1, &display_fbo_);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, display_fbo_);
    gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, display_, 0);
    if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("mesh renderer: framebuffer incomplete");
}

void MeshRenderer::render(const Scene& scene, Interpolation interpolation, ShaderMode mode) {
    if (!index_count_) throw std::runtime_error("mesh renderer: call set_tessellation first");
    std::vector<const Object*> objects;
    std::vector<float> records;
    for (const Object& object : scene.objects) {
        if (is_translucent(object.material.model))
            throw std::runtime_error("mesh renderer: translucent objects are not supported");
        objects.push_back(&object);
        pack_material(object.material, records);
    }
    if (records.empty()) records.resize(kMaterialTexels * 4, 0.0f);
    ensure_targets(scene.display.width, scene.display.height);
    const CameraFrame frame = make_camera_frame(scene.camera, scene.display, scene.objects);
    const LightUniforms lights = pack_lights(scene.lights);

    gl_.BindBuffer(GL_TEXTURE_BUFFER, material_buffer_);
    gl_.BufferData(GL_TEXTURE_BUFFER, GLsizeiptr(records.size() * sizeof(float)), records.data(), GL_STREAM_DRAW);
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.BindTexture(GL_TEXTURE_BUFFER, material_texture_);
    gl_.TexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, material_buffer_);

    std::vector<std::string> defines = specialization_defines(mode, objects, scene.lights);
    if (interpolation == Interpolation::gouraud) defines.push_back("GOURAUD");
    const unsigned program = programs_.get({"passes/mesh_sphere.vert", "passes/mesh_sphere.frag", defines});

    gl_.BindFramebuffer(GL_FRAMEBUFFER, scene_fbo_);
    gl_.Viewport(0, 0, width_, height_);
    const float background[4] = {float(scene.background.r), float(scene.background.g), float(scene.background.b),
                                 1.0f};
    gl_.ClearBufferfv(GL_COLOR, 0, background);
    const float far_depth = 1.0f;
    gl_.ClearBufferfv(GL_DEPTH, 0, &far_depth);
    gl_.Enable(GL_DEPTH_TEST);
    gl_.DepthFunc(GL_LESS);
    gl_.DepthMask(GL_TRUE);
    gl_.Disable(GL_BLEND);
    gl_.Enable(GL_CULL_FACE);  // default: back faces of counter-clockwise triangles

    gl_.UseProgram(program);
    set_camera_uniforms(gl_, program, frame);
    auto loc = [&](const char* name) { return gl_.GetUniformLocation(program, name); };
    upload_lights(gl_, program, lights);
    gl_.BindVertexArray(vao_);
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& object = scene.objects[i];
        gl_.Uniform4f(loc("u_sphere"), float(object.center.x), float(object.center.y), float(object.center.z),
                      float(object.radius));
        gl_.Uniform1i(loc("u_material"), int(i));
        gl_.DrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
    }
    gl_.Disable(GL_CULL_FACE);
    gl_.Disable(GL_DEPTH_TEST);

    // The same quantize pass as the Renderer, so the frame does the same work.
    const unsigned quantize = programs_.get({"passes/fullscreen.vert", "passes/quantize.frag", {}});
    gl_.BindFramebuffer(GL_FRAMEBUFFER, display_fbo_);
    gl_.UseProgram(quantize);
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.BindTexture(GL_TEXTURE_2D, colour_);
    gl_.Uniform1i(gl_.GetUniformLocation(quantize, "u_colour"), 0);
    gl_.Uniform1i(gl_.GetUniformLocation(quantize, "u_bits"), scene.display.bits);
    gl_.Uniform1i(gl_.GetUniformLocation(quantize, "u_dither"), scene.display.dither ? 1 : 0);
    gl_.BindVertexArray(empty_vao_);
    gl_.DrawArrays(GL_TRIANGLES, 0, 3);
    gl_.BindVertexArray(0);
    gl_.UseProgram(0);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
}

RgbFloatImage MeshRenderer::read_raw() const {
    RgbFloatImage image;
    image.width = width_, image.height = height_;
    image.pixels.resize(std::size_t(width_) * height_ * 3);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, scene_fbo_);
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_.ReadPixels(0, 0, width_, height_, GL_RGB, GL_FLOAT, image.pixels.data());
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
    return image;
}

}  // namespace m3055::bench
