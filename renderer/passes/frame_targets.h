// The plumbing of one frame, in one place for everything that renders a scene
// (through frame/frame_sequence.h: the Renderer, and the benchmark's UV-sphere
// renderer): the float scene target with its depth buffer (render_targets.h),
// the display target, the material records (material_texture.h), the objects
// as shadow rays meet them (occluders.h), the clear to
// the background, the quantize pass (docs/spec.md#2-display) and the read-backs.
#pragma once

#include "gl/gl_api.h"
#include "gl/gl_object.h"
#include "gl/program.h"
#include "image/image.h"
#include "passes/material_texture.h"
#include "passes/occluders.h"
#include "passes/render_targets.h"
#include "scene/scene.h"

#include <vector>

namespace m3055 {

class FrameTargets {
public:
    FrameTargets(const GlApi& gl, ProgramCache& programs);

    // Starts a frame of `scene`: targets at the display's size (kept while the
    // size stays), the objects' material records uploaded (u_materials, unit 0),
    // the occluders uploaded when a light casts shadows (u_occluders, unit 3),
    // the scene target bound, cleared to the background and depth 1, with depth
    // test LESS, depth writes on and blending off.
    void begin(const Scene& scene);

    // Gives the scene target a stencil from the next begin on (the two-pass
    // translucent blend, passes/translucent_blend.h), or takes it away.
    void set_stencil(bool on) { scene_.set_stencil(on); }

    // Sets a program's material uniforms (the sampler's unit, the record stride); call after UseProgram.
    void set_material_uniforms(unsigned program) const;
    // Sets a program's occluder uniforms (shadows); call after UseProgram.
    void set_occluder_uniforms(unsigned program) const { occluders_.set_uniforms(program); }

    // The quantize pass (docs/spec.md#2-display: display bits, optional dither) from the scene
    // target into the display target; leaves framebuffer 0 bound.
    void quantize(const Display& display);

    // `small`'s display and scene colour spread (nearest) over width x height
    // here, the targets made that size; leaves framebuffer 0 bound.
    void show_scaled(const FrameTargets& small, int width, int height);

    // The quantized display as an RGBA8 GL texture (GL_NEAREST; row 0 at the bottom).
    unsigned display_texture() const { return display_texture_.id(); }
    int width() const { return scene_.width(); }
    int height() const { return scene_.height(); }

    Rgb8Image read_display() const;  // 8-bit PNG values, rows top to bottom
    RgbFloatImage read_raw() const;  // unquantized linear colour, rows bottom to top

private:
    void ensure_size(int width, int height);

    const GlApi& gl_;
    ProgramCache& programs_;
    FloatTargets scene_;  // the float colour the passes draw into, with depth
    GlTexture display_texture_;
    GlFramebuffer display_fbo_;
    MaterialTexture materials_;
    OccluderTexture occluders_;
    GlVertexArray empty_vao_;  // the quantize pass's fullscreen triangle has no attributes
};

}  // namespace m3055
