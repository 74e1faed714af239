// How the translucent pass composites (docs/spec.md#42-translucent): each
// fragment gives a premultiplied colour c and a per-channel transmittance t,
// and the target becomes dst = c + t * dst.
//   dual_source  one draw, glBlendFunc(GL_ONE, GL_SRC1_COLOR): c and t are the
//                fragment's two outputs (GL 3.3; WebGL2 only through the
//                optional WEBGL_blend_func_extended).
//   two_pass     per layer of fragments, a multiply draw (dst * t,
//                glBlendFunc(GL_ZERO, GL_SRC_COLOR)) then an add draw (+ c,
//                glBlendFunc(GL_ONE, GL_ONE)), each fragment's t and c its one
//                output. In float targets fl(fl(dst * t) + c) is what the
//                one-draw blend computes, so the pixels are the same, provided
//                every fragment's multiply comes right before its add. Where a
//                draw may cover a pixel more than once (a torus's two front
//                faces) it is repeated per layer: the stencil counts each
//                pixel's fragments in primitive order and layer k lets only
//                the k-th through (GL_EQUAL k); layers go on while an
//                occlusion query finds a pixel with more. The Renderer draws
//                spheres in groups that cover no pixel twice, and convex
//                meshes (back faces culled) cover none twice: one layer.
#pragma once

#include "gl/gl_api.h"
#include "gl/gl_object.h"

#include <functional>

namespace m3055 {

enum class TranslucentBlend { dual_source, two_pass };

// The blend a new renderer uses: two_pass when the environment variable
// M3055_NO_DUAL_SOURCE is set to anything but "" or "0" (the one place it is
// read), or when the context has no dual-source blending
// (GL_MAX_DUAL_SOURCE_DRAW_BUFFERS below 1); dual_source otherwise.
TranslucentBlend default_translucent_blend(const GlApi& gl);

// The shader define of the two-pass programs: one output, chosen by the
// uniform u_blend_step (0: the transmittance, 1: the colour).
inline constexpr const char* kTwoPassBlendDefine = "TWO_PASS_BLEND";

// Draws translucent geometry with the program in use, into a target with a
// stencil, depth test on and depth writes off (the Renderer's translucent pass).
class TranslucentBlender {
public:
    explicit TranslucentBlender(const GlApi& gl);

    // Sets the blend state of `mode` for the draws that follow (dual_source:
    // the blend function; two_pass: nothing until draw).
    void begin(TranslucentBlend mode) const;

    // two_pass: runs `draw` (the same primitives every time) per layer, as the
    // header says, leaving the stencil test off. `single_layer`: the caller
    // knows no pixel is covered twice (one convex mesh with back faces culled),
    // so the layer query is skipped. Throws std::runtime_error past 254 layers
    // (the stencil's range).
    void draw_two_pass(unsigned program, const std::function<void()>& draw, bool single_layer) const;

private:
    const GlApi& gl_;
    GlQuery query_;
};

}  // namespace m3055
