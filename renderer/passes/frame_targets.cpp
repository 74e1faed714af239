#include "passes/frame_targets.h"

#include "passes/material_buffer.h"
#include "passes/material_slots.h"
#include "passes/spectral_tables.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace m3055 {

FrameTargets::FrameTargets(const GlApi& gl, ProgramCache& programs)
    : gl_(gl), programs_(programs), scene_(gl, 1, true, "scene"), display_texture_(gl), display_fbo_(gl),
      materials_(gl), occluders_(gl), empty_vao_(gl) {}

void FrameTargets::ensure_size(int width, int height) {
    if (width == scene_.width() && height == scene_.height()) return;
    // The display first: the scene target takes the new size only once both
    // are complete, so a failed resize is tried again by the next frame.
    define_texture_2d(gl_, display_texture_, kRgba8, width, height, nullptr);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, display_fbo_.id());
    gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, display_texture_.id(), 0);
    check_framebuffer(gl_, "display", width, height);
    scene_.ensure_size(width, height);
}

void FrameTargets::begin(const Scene& scene) {
    ensure_size(scene.display.width, scene.display.height);
    const MaterialSlots slots = material_slots(scene.objects);
    std::vector<float> records;
    records.reserve(slots.records.size() * std::size_t(material_record_texels()) * 4);
    for (const Material* material : slots.records) pack_material(*material, records);
    append_spectral_tables(slots.records, scene.lights, records);
    materials_.upload(records);
    const bool shadows = std::any_of(scene.lights.begin(), scene.lights.end(), [](const Light& light) {
        return light.shadow && light.enabled && light.intensity > 0.0;
    });
    if (shadows) occluders_.upload(scene);
    const int w = width(), h = height();
    gl_.BindFramebuffer(GL_FRAMEBUFFER, scene_.framebuffer());
    gl_.Viewport(0, 0, w, h);
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

void FrameTargets::set_material_uniforms(unsigned program) const { materials_.set_uniforms(program); }

void FrameTargets::quantize(const Display& display) {
    gl_.Disable(GL_DEPTH_TEST);
    std::vector<std::string> defines;
    if (display.dither) defines.push_back("DITHER");
    if (display.view_transform == ViewTransform::srgb) defines.push_back("SRGB");
    const unsigned program = programs_.get({"passes/fullscreen.vert", "passes/quantize.frag", defines});
    gl_.BindFramebuffer(GL_FRAMEBUFFER, display_fbo_.id());
    gl_.Viewport(0, 0, width(), height());
    gl_.UseProgram(program);
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.BindTexture(GL_TEXTURE_2D, scene_.colour(0));
    gl_.Uniform1i(gl_.GetUniformLocation(program, "u_colour"), 0);
    gl_.Uniform1i(gl_.GetUniformLocation(program, "u_bits"), display.bits);
    gl_.BindVertexArray(empty_vao_.id());
    gl_.DrawArrays(GL_TRIANGLES, 0, 3);
    gl_.BindVertexArray(0);
    gl_.UseProgram(0);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
}

void FrameTargets::show_scaled(const FrameTargets& small, int width, int height) {
    ensure_size(width, height);
    const int w = small.width(), h = small.height();
    const std::pair<unsigned, unsigned> pairs[2] = {{small.display_fbo_.id(), display_fbo_.id()},
                                                    {small.scene_.framebuffer(), scene_.framebuffer()}};
    for (const auto& [from, to] : pairs) {
        gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, from);
        gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, to);
        gl_.BlitFramebuffer(0, 0, w, h, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
}

// Readbacks go in strips of rows: Mesa converts a read through a temporary
// as large as the rectangle read (1 GiB for the raw image at 8192 x 8192),
// so one whole-image read held that beside the image itself.
constexpr int kReadRows = 256;

Rgb8Image FrameTargets::read_display() const {
    const int w = width(), h = height();
    Rgb8Image image;
    image.width = w, image.height = h;
    image.pixels.resize(std::size_t(w) * h * 3);
    std::vector<unsigned char> rgba(std::size_t(w) * std::min(h, kReadRows) * 4);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, display_fbo_.id());
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    for (int y0 = 0; y0 < h; y0 += kReadRows) {
        const int rows = std::min(kReadRows, h - y0);
        gl_.ReadPixels(0, y0, w, rows, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        for (int r = 0; r < rows; ++r) {  // GL rows run bottom to top, PNG rows top to bottom
            const unsigned char* src = &rgba[std::size_t(r) * w * 4];
            unsigned char* dst = &image.pixels[std::size_t(h - 1 - (y0 + r)) * w * 3];
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c) dst[x * 3 + c] = src[x * 4 + c];
        }
    }
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
    return image;
}

RgbFloatImage FrameTargets::read_raw() const {
    const int w = width(), h = height();
    RgbFloatImage image;
    image.width = w, image.height = h;
    image.pixels.resize(std::size_t(w) * h * 3);
    // Read as RGBA: GLES/WebGL2 allow no RGB float read-back, and the floats are the same.
    std::vector<float> rgba(std::size_t(w) * std::min(h, kReadRows) * 4);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, scene_.framebuffer());
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);
    for (int y0 = 0; y0 < h; y0 += kReadRows) {
        const int rows = std::min(kReadRows, h - y0);
        gl_.ReadPixels(0, y0, w, rows, GL_RGBA, GL_FLOAT, rgba.data());
        float* dst = image.pixels.data() + std::size_t(y0) * w * 3;
        for (std::size_t i = 0; i < std::size_t(w) * std::size_t(rows); ++i)
            for (std::size_t c = 0; c < 3; ++c) dst[i * 3 + c] = rgba[i * 4 + c];
    }
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
    return image;
}

}  // namespace m3055
