#include "passes/frame_targets.h"

#include "passes/material_buffer.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace m3055 {

FrameTargets::FrameTargets(const GlApi& gl, ProgramCache& programs) : gl_(gl), programs_(programs) {
    gl_.GenBuffers(1, &material_buffer_);
    gl_.GenTextures(1, &material_texture_);
    gl_.GenVertexArrays(1, &empty_vao_);
}

FrameTargets::~FrameTargets() {
    release();
    gl_.DeleteBuffers(1, &material_buffer_);
    gl_.DeleteTextures(1, &material_texture_);
    gl_.DeleteVertexArrays(1, &empty_vao_);
}

void FrameTargets::release() {
    if (!scene_fbo_) return;
    gl_.DeleteFramebuffers(1, &scene_fbo_);
    gl_.DeleteFramebuffers(1, &display_fbo_);
    const unsigned textures[] = {colour_texture_, depth_texture_, display_texture_};
    gl_.DeleteTextures(3, textures);
    scene_fbo_ = display_fbo_ = 0;
}

unsigned FrameTargets::make_texture(int internal_format, unsigned format, unsigned type) const {
    unsigned texture = 0;
    gl_.GenTextures(1, &texture);
    gl_.BindTexture(GL_TEXTURE_2D, texture);
    gl_.TexImage2D(GL_TEXTURE_2D, 0, internal_format, width_, height_, 0, format, type, nullptr);
    // Nearest: the explorer shows the display's dots as they are.
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return texture;
}

void FrameTargets::check_framebuffer(const char* name) const {
    const GLenum status = gl_.CheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error(std::string("the ") + name + " framebuffer is incomplete (status " +
                                 std::to_string(status) + ") at " + std::to_string(width_) + "x" +
                                 std::to_string(height_));
}

void FrameTargets::ensure_size(int width, int height) {
    if (scene_fbo_ && width == width_ && height == height_) return;
    release();
    width_ = width, height_ = height;
    // Float colour: the raw output is unquantized and unclamped (metals exceed 1).
    colour_texture_ = make_texture(GL_RGBA32F, GL_RGBA, GL_FLOAT);
    depth_texture_ = make_texture(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT);
    display_texture_ = make_texture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE);
    gl_.GenFramebuffers(1, &scene_fbo_);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, scene_fbo_);
    gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_texture_, 0);
    gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_texture_, 0);
    check_framebuffer("scene");
    gl_.GenFramebuffers(1, &display_fbo_);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, display_fbo_);
    gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, display_texture_, 0);
    check_framebuffer("display");
}

void FrameTargets::upload_materials(const std::vector<Object>& objects) {
    std::vector<float> records;
    records.reserve(objects.size() * std::size_t(material_record_texels()) * 4);
    for (const Object& object : objects) pack_material(object.material, records);
    if (records.empty()) records.resize(std::size_t(material_record_texels()) * 4, 0.0f);
    gl_.BindBuffer(GL_TEXTURE_BUFFER, material_buffer_);
    gl_.BufferData(GL_TEXTURE_BUFFER, GLsizeiptr(records.size() * sizeof(float)), records.data(), GL_STREAM_DRAW);
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.BindTexture(GL_TEXTURE_BUFFER, material_texture_);
    gl_.TexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, material_buffer_);
}

void FrameTargets::begin(const Scene& scene) {
    ensure_size(scene.display.width, scene.display.height);
    upload_materials(scene.objects);
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
}

void FrameTargets::set_material_uniforms(unsigned program) const {
    gl_.Uniform1i(gl_.GetUniformLocation(program, "u_material_texels"), material_record_texels());
}

void FrameTargets::quantize(const Display& display) {
    gl_.Disable(GL_DEPTH_TEST);
    const unsigned program = programs_.get({"passes/fullscreen.vert", "passes/quantize.frag", {}});
    gl_.BindFramebuffer(GL_FRAMEBUFFER, display_fbo_);
    gl_.Viewport(0, 0, width_, height_);
    gl_.UseProgram(program);
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.BindTexture(GL_TEXTURE_2D, colour_texture_);
    gl_.Uniform1i(gl_.GetUniformLocation(program, "u_colour"), 0);
    gl_.Uniform1i(gl_.GetUniformLocation(program, "u_bits"), display.bits);
    gl_.Uniform1i(gl_.GetUniformLocation(program, "u_dither"), display.dither ? 1 : 0);
    gl_.BindVertexArray(empty_vao_);
    gl_.DrawArrays(GL_TRIANGLES, 0, 3);
    gl_.BindVertexArray(0);
    gl_.UseProgram(0);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
}

// Readbacks go in strips of rows: Mesa converts a read through a temporary
// as large as the rectangle read (1 GiB for the raw image at 8192 x 8192),
// so one whole-image read held that beside the image itself.
constexpr int kReadRows = 256;

Rgb8Image FrameTargets::read_display() const {
    Rgb8Image image;
    image.width = width_, image.height = height_;
    image.pixels.resize(std::size_t(width_) * height_ * 3);
    std::vector<unsigned char> rgba(std::size_t(width_) * std::min(height_, kReadRows) * 4);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, display_fbo_);
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    for (int y0 = 0; y0 < height_; y0 += kReadRows) {
        const int rows = std::min(kReadRows, height_ - y0);
        gl_.ReadPixels(0, y0, width_, rows, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        for (int r = 0; r < rows; ++r) {  // GL rows run bottom to top, PNG rows top to bottom
            const unsigned char* src = &rgba[std::size_t(r) * width_ * 4];
            unsigned char* dst = &image.pixels[std::size_t(height_ - 1 - (y0 + r)) * width_ * 3];
            for (int x = 0; x < width_; ++x)
                for (int c = 0; c < 3; ++c) dst[x * 3 + c] = src[x * 4 + c];
        }
    }
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
    return image;
}

RgbFloatImage FrameTargets::read_raw() const {
    RgbFloatImage image;
    image.width = width_, image.height = height_;
    image.pixels.resize(std::size_t(width_) * height_ * 3);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, scene_fbo_);
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    for (int y0 = 0; y0 < height_; y0 += kReadRows)
        gl_.ReadPixels(0, y0, width_, std::min(kReadRows, height_ - y0), GL_RGB, GL_FLOAT,
                       image.pixels.data() + std::size_t(y0) * width_ * 3);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
    return image;
}

}  // namespace m3055
