// The plumbing of one frame, in one place for everything that renders a scene
// (the Renderer, and the benchmark's UV-sphere renderer): the float scene
// target with its depth buffer, the display target, the material records, the
// clear to the background, the quantize pass (docs/spec.md#2-display) and the read-backs.
#pragma once

#include "gl/gl_api.h"
#include "gl/program.h"
#include "image/image.h"
#include "scene/scene.h"

#include <vector>

namespace m3055 {

class FrameTargets {
public:
    FrameTargets(const GlApi& gl, ProgramCache& programs);
    ~FrameTargets();
    FrameTargets(const FrameTargets&) = delete;
    FrameTargets& operator=(const FrameTargets&) = delete;

    // Starts a frame of `scene`: targets at the display's size (kept while the
    // size stays), the objects' material records uploaded (u_materials, unit 0),
    // the scene target bound, cleared to the background and depth 1, with depth
    // test LESS, depth writes on and blending off.
    void begin(const Scene& scene);

    // Sets a program's material uniforms (the record stride); call after UseProgram.
    void set_material_uniforms(unsigned program) const;

    // The quantize pass (docs/spec.md#2-display: display bits, optional dither) from the scene
    // target into the display target; leaves framebuffer 0 bound.
    void quantize(const Display& display);

    // The quantized display as an RGBA8 GL texture (GL_NEAREST; row 0 at the bottom).
    unsigned display_texture() const { return display_texture_; }
    int width() const { return width_; }
    int height() const { return height_; }

    Rgb8Image read_display() const;  // 8-bit PNG values, rows top to bottom
    RgbFloatImage read_raw() const;  // unquantized linear colour, rows bottom to top

private:
    void ensure_size(int width, int height);
    void release();
    void upload_materials(const std::vector<Object>& objects);
    unsigned make_texture(int internal_format, unsigned format, unsigned type) const;
    void check_framebuffer(const char* name) const;

    const GlApi& gl_;
    ProgramCache& programs_;
    unsigned scene_fbo_ = 0, colour_texture_ = 0, depth_texture_ = 0;
    unsigned display_fbo_ = 0, display_texture_ = 0;
    unsigned material_buffer_ = 0, material_texture_ = 0, empty_vao_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace m3055
