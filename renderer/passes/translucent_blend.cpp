#include "passes/translucent_blend.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace m3055 {

TranslucentBlend default_translucent_blend(const GlApi& gl) {
    const char* no_dual_source = std::getenv("M3055_NO_DUAL_SOURCE");
    if (no_dual_source && *no_dual_source && std::string(no_dual_source) != "0") return TranslucentBlend::two_pass;
#ifdef __EMSCRIPTEN__
    // WebGL2 has dual-source blending only as WEBGL_blend_func_extended, which
    // Emscripten 3.1.6's GL layer does not expose: the exact two passes (docs/web.md).
    (void)gl;
    return TranslucentBlend::two_pass;
#else
    GLint buffers = 0;
    gl.GetIntegerv(GL_MAX_DUAL_SOURCE_DRAW_BUFFERS, &buffers);
    if (buffers >= 1) return TranslucentBlend::dual_source;
    // Where the feature is absent the enum itself may be unknown
    // (GL_INVALID_ENUM): that error is this query's, not the caller's.
    while (gl.GetError() != GL_NO_ERROR) {
    }
    return TranslucentBlend::two_pass;
#endif
}

TranslucentBlender::TranslucentBlender(const GlApi& gl) : gl_(gl), query_(gl) {}

void TranslucentBlender::begin(TranslucentBlend mode) const {
    gl_.Enable(GL_BLEND);
    gl_.BlendEquation(GL_FUNC_ADD);
    if (mode == TranslucentBlend::dual_source) gl_.BlendFunc(GL_ONE, GL_SRC1_COLOR);
}

// The stencil counts 0..255; layer 254 is the last whose successor can still be asked about.
constexpr int kMaxLayers = 254;
#ifdef __EMSCRIPTEN__
constexpr int kWebGlLayers = 4;
#endif

void TranslucentBlender::draw_two_pass(unsigned program, const std::function<void()>& draw, bool single_layer) const {
    const GLint step = gl_.GetUniformLocation(program, "u_blend_step");
    const GLint zero = 0;
    gl_.Enable(GL_STENCIL_TEST);
    gl_.StencilMask(0xFF);
    for (int layer = 0;; ++layer) {
        if (layer == kMaxLayers)
            throw std::runtime_error("the two-pass translucent blend met more than " + std::to_string(kMaxLayers) +
                                     " fragments of one draw on one pixel");
        // Every fragment, depth test passed or not, counts: the multiply and
        // the add draw then pick the same k-th fragment of each pixel.
        gl_.StencilOp(GL_INCR, GL_INCR, GL_INCR);
        gl_.StencilFunc(GL_EQUAL, layer, 0xFF);
        for (int add = 0; add < 2; ++add) {
            gl_.ClearBufferiv(GL_STENCIL, 0, &zero);
            if (add) gl_.BlendFunc(GL_ONE, GL_ONE);
            else gl_.BlendFunc(GL_ZERO, GL_SRC_COLOR);
            gl_.Uniform1i(step, add);
            draw();
        }
        if (single_layer) break;
#ifdef __EMSCRIPTEN__
        // WebGL gives a query's result only after the frame has gone back to
        // the browser, so the question below cannot be asked: the layers a
        // draw of this renderer can put on one pixel are drawn instead. The
        // only draw that is not single-layer is a translucent torus with back
        // faces culled, which a line enters at most twice (kWebGlLayers leaves
        // room for its polygonal surface at grazing angles); a layer past a
        // pixel's count draws nothing there.
        if (layer + 1 >= kWebGlLayers) break;
        continue;
#endif
        // The stencil now holds each pixel's fragment count: is any above layer + 1?
        gl_.StencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        gl_.StencilFunc(GL_LESS, layer + 1, 0xFF);  // passes where layer + 1 < count
        gl_.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        gl_.Disable(GL_DEPTH_TEST);
        gl_.BeginQuery(GL_ANY_SAMPLES_PASSED, query_.id());
        draw();
        gl_.EndQuery(GL_ANY_SAMPLES_PASSED);
        gl_.Enable(GL_DEPTH_TEST);
        gl_.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        GLuint more = 0;
        gl_.GetQueryObjectuiv(query_.id(), GL_QUERY_RESULT, &more);
        if (!more) break;
    }
    gl_.Disable(GL_STENCIL_TEST);
}

}  // namespace m3055
