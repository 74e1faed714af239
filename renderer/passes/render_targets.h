// Textures and framebuffers of the GPU passes, set up one way: 2D textures
// with nearest filtering and edges clamped (the passes read texels, never
// filtered values), and float render targets (RGBA32F colour attachments,
// optionally a float depth attachment) for the frame's scene target, the BRDF
// grid and the stress harness.
#pragma once

#include "gl/gl_api.h"
#include "gl/gl_object.h"

#include <vector>

namespace m3055 {

struct TextureFormat {
    int internal_format;
    unsigned format, type;
};
inline constexpr TextureFormat kRgba32f{GL_RGBA32F, GL_RGBA, GL_FLOAT};
inline constexpr TextureFormat kDepth32f{GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT};
// The same depth with an 8-bit stencil (the two-pass translucent
// blend's fragment counts, passes/translucent_blend.h).
inline constexpr TextureFormat kDepth32fStencil8{GL_DEPTH32F_STENCIL8, GL_DEPTH_STENCIL,
                                                 GL_FLOAT_32_UNSIGNED_INT_24_8_REV};
inline constexpr TextureFormat kRgba8{GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};

// (Re)defines `texture` as width x height of `format`, from `pixels` (or
// undefined when null), on the active unit; leaves it bound to GL_TEXTURE_2D.
void define_texture_2d(const GlApi& gl, const GlTexture& texture, TextureFormat format, int width, int height,
                       const void* pixels);

// Throws std::runtime_error naming the framebuffer (`name`) and its size when
// the bound one is incomplete.
void check_framebuffer(const GlApi& gl, const char* name, int width, int height);

// A framebuffer of `colours` RGBA32F colour attachments (drawn into all at
// once: DrawBuffers) and, with `depth`, a 32-bit float depth attachment, with
// an 8-bit stencil after set_stencil(true).
class FloatTargets {
public:
    FloatTargets(const GlApi& gl, int colours, bool depth, const char* name);

    // Makes the targets width x height (kept while the size stays) and leaves
    // the framebuffer bound.
    void ensure_size(int width, int height);
    // A stencil beside the depth from the next ensure_size on (or none again):
    // only the two-pass translucent blend needs one, and at 8192 x 8192 it
    // doubles the depth's memory (llvmpipe keeps 64 bits a pixel).
    void set_stencil(bool on);
    unsigned framebuffer() const { return framebuffer_.id(); }
    unsigned colour(int attachment) const { return colours_[std::size_t(attachment)].id(); }
    int width() const { return width_; }
    int height() const { return height_; }

    // Colour attachment `attachment`, RGBA per pixel, rows bottom to top.
    std::vector<float> read_rgba(int attachment) const;

private:
    const GlApi& gl_;
    const char* name_;
    std::vector<GlTexture> colours_;
    GlTexture depth_;
    GlFramebuffer framebuffer_;
    int width_ = 0, height_ = 0;
    bool stencil_ = false;
};

}  // namespace m3055
