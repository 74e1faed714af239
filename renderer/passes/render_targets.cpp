#include "passes/render_targets.h"

#include <stdexcept>
#include <string>

namespace m3055 {

void define_texture_2d(const GlApi& gl, const GlTexture& texture, TextureFormat format, int width, int height,
                       const void* pixels) {
    gl.BindTexture(GL_TEXTURE_2D, texture.id());
    gl.TexImage2D(GL_TEXTURE_2D, 0, format.internal_format, width, height, 0, format.format, format.type, pixels);
    // Nearest: the explorer shows the display's dots as they are, and the
    // GPU evaluations read their inputs texel by texel.
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void check_framebuffer(const GlApi& gl, const char* name, int width, int height) {
    const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error(std::string("the ") + name + " framebuffer is incomplete (status " +
                                 std::to_string(status) + ") at " + std::to_string(width) + "x" +
                                 std::to_string(height));
}

FloatTargets::FloatTargets(const GlApi& gl, int colours, bool depth, const char* name)
    : gl_(gl), name_(name), framebuffer_(gl) {
    for (int i = 0; i < colours; ++i) colours_.emplace_back(gl);
    if (depth) depth_ = GlTexture(gl);
}

void FloatTargets::set_stencil(bool on) {
    if (on == stencil_) return;
    stencil_ = on;
    width_ = height_ = 0;  // redefined at the next ensure_size
}

void FloatTargets::ensure_size(int width, int height) {
    gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    if (width == width_ && height == height_) return;
    std::vector<GLenum> buffers;
    for (std::size_t i = 0; i < colours_.size(); ++i) {
        // Float colour: outputs unquantized and unclamped (metals exceed 1).
        define_texture_2d(gl_, colours_[i], kRgba32f, width, height, nullptr);
        buffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
        gl_.FramebufferTexture2D(GL_FRAMEBUFFER, buffers.back(), GL_TEXTURE_2D, colours_[i].id(), 0);
    }
    if (depth_ && stencil_) {
        define_texture_2d(gl_, depth_, kDepth32fStencil8, width, height, nullptr);
        gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, depth_.id(), 0);
    } else if (depth_) {
        // No stencil left attached from an earlier size with one.
        gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
        define_texture_2d(gl_, depth_, kDepth32f, width, height, nullptr);
        gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.id(), 0);
    }
    gl_.DrawBuffers(GLsizei(buffers.size()), buffers.data());
    check_framebuffer(gl_, name_, width, height);
    width_ = width, height_ = height;  // only once complete: a failed size is tried again
}

std::vector<float> FloatTargets::read_rgba(int attachment) const {
    std::vector<float> rgba(std::size_t(width_) * std::size_t(height_) * 4);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    gl_.ReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + attachment));
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);
    gl_.ReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, rgba.data());
    return rgba;
}

}  // namespace m3055
