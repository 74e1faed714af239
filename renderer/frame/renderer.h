// The GPU renderer: draws a Scene through the GLSL 3.3 pipeline into offscreen
// targets at the display's own size (docs/spec.md#2-display to #4-paper-models):
//   opaque spheres -> translucent spheres, back to front -> quantize pass.
// It needs a current GL 3.3 core context whose functions are in `gl`; it makes
// no context itself (see gl/context.h for headless ones; the explorer makes a
// window's).
#pragma once

#include "gl/gl_api.h"
#include "gl/program.h"
#include "frame/render_error.h"
#include "image/image.h"
#include "passes/display_region.h"
#include "passes/light_uniforms.h"
#include "passes/shader_plan.h"
#include "passes/translucent_blend.h"
#include "scene/scene.h"

#include <chrono>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace m3055 {

class Renderer {
public:
    // Programs come from `programs`, the context's one cache, shared with
    // whatever else draws there (another Renderer, the BRDF grid), so each
    // program compiles once per context. The cache must outlive the Renderer.
    Renderer(const GlApi& gl, ProgramCache& programs);
    explicit Renderer(const GlApi& gl);  // with a program cache of its own
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Renders `scene` at scene.display.width x height. Throws ShaderError with
    // the GL log (shader file name and line) if a program fails to build,
    // RenderTimeout past a deadline (frame/render_error.h).
    void render(const Scene& scene);
    // The explorer's preview of a costly scene while input comes: drawn at
    // 1/divisor of the display's width and height, then spread over the
    // display's own pixels (nearest), so the display, its texture and its
    // read-backs keep the scene's size. divisor <= 1: render(scene).
    void render_reduced(const Scene& scene, int divisor);
    // The box `region` of the display drawn again, with the specialized
    // programs; the other pixels keep what they show. Each pixel is what
    // render(scene) gives it, so regions covering the display give render's
    // image: the explorer refines a preview this way without holding input
    // for a whole frame. The display must already be at the scene's size
    // (std::logic_error otherwise).
    void render_region(const Scene& scene, const DisplayRegion& region);

    // How area and sky lights are sampled (passes/light_uniforms.h):
    // kRenderSampling by default, what the command line renders with; the
    // explorer takes kFastSampling while a slider moves. Scenes without area
    // lights are the same under every sampling.
    void set_area_sampling(AreaSampling sampling);
    AreaSampling area_sampling() const;

    // Specialized programs (the default) are compiled per scene shape and
    // cached; general ones serve every scene. Both give the same pixels.
    void set_shader_mode(ShaderMode mode);
    // How translucent objects are composited (passes/translucent_blend.h):
    // dual-source blending in one draw, or a multiply and an add draw per
    // layer of fragments; the same display levels either way. A new renderer
    // takes default_translucent_blend (M3055_NO_DUAL_SOURCE, or no dual-source
    // blending in the context, gives two_pass).
    void set_translucent_blend(TranslucentBlend blend);
    TranslucentBlend translucent_blend() const;
    // A time budget for the following renders: with a
    // deadline, each draw is split into chunks of bounded work
    // (passes/draw_chunks.h), the GPU is waited for between them, and render()
    // throws RenderTimeout at the first boundary past the deadline. The pixels
    // are the same as without one (the draws are only split). std::nullopt,
    // the default: no waiting; spheres in one draw call a pass, meshes still
    // in chunks (with a flush between, which bounds llvmpipe's memory).
    void set_deadline(std::optional<std::chrono::steady_clock::time_point> deadline);

    // The explorer's "no stall on a new specialization": with deferral on, a
    // render whose specialized program is not built yet draws with the
    // general program (which gives the same pixels, byte for byte) and notes
    // it; when the explorer is idle, render_specialized() draws the same scene
    // again with its specialized programs (built then, and run once, as
    // llvmpipe compiles a program's code at its first draw), so later renders
    // use them. A specialized program whose general stand-in is not built
    // either (area lights or shadows: not warmed up) is built at once instead.
    // Off by default: the command line's renders are unchanged.
    void set_defer_compiles(bool on);
    bool defers_compiles() const;
    std::size_t deferred_programs() const;  // noted since the last render_specialized
    void render_specialized(const Scene& scene);
    // At start-up: builds and runs the general programs of every pass (a small
    // scene with opaque and translucent spheres and meshes, every light kind),
    // so that with deferral no later render compiles anything. Leaves the
    // display targets at that scene's size (the next render resizes them).
    void warm_up_general_programs();

    // Number of programs compiled so far in its cache (shared: by every user).
    std::size_t compiled_programs() const;

    // The quantized display image of the last render, as an RGBA8 GL texture
    // (GL_NEAREST filtering; row 0 at the bottom, as GL textures are).
    unsigned display_texture() const;
    int width() const;
    int height() const;

    // Readback of the last render.
    Rgb8Image read_display() const;  // 8-bit PNG values, rows top to bottom
    RgbFloatImage read_raw() const;  // unquantized linear colour, rows bottom to top

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace m3055
