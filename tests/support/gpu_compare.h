// Renders a scene on the GPU (headless context, llvmpipe) and with the CPU
// reference, and measures how far apart they are.
#pragma once

#include "passes/shader_plan.h"
#include "reference/reference.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace m3055 {
class Renderer;   // frame/renderer.h
struct GlApi;     // gl/gl_api.h
}  // namespace m3055

namespace m3055::test {

struct Comparison {
    double max_abs_diff = 0;     // over interior pixels, unquantized colour
    double max_scaled_diff = 0;  // |gpu - ref| / max(1, |ref|): what the tolerance bounds
    double mean_abs_diff = 0;
    double mean_signed_diff = 0;  // gpu - ref: a bias, where mean |diff| is also noise
    double same_level_share = 0; // share of interior pixels on the same display level (all channels)
    int max_level_diff = 0;      // largest level difference on interior pixels
    long interior_pixels = 0;
    long nonfinite_values = 0;   // NaN or Inf anywhere in the GPU's raw output
    std::string describe() const;
};

// Shared headless GL context + renderer for the whole test process.
Comparison compare_gpu_with_reference(const Scene& scene, ShaderMode mode = ShaderMode::specialized);
// The GPU's render of `scene` against the CPU reference of `reference_scene`
// (same geometry and lights; e.g. a .brdf model against the built-in it copies).
Comparison compare_gpu_with_reference_of(const Scene& scene, const Scene& reference_scene,
                                         ShaderMode mode = ShaderMode::specialized);
// `scene` on the GPU against its reference rendered before (ref::render_reference(scene)):
// for a test that renders one scene several ways (the reference is most of the time).
Comparison compare_gpu_with(const Scene& scene, const ref::ReferenceImage& reference,
                            ShaderMode mode = ShaderMode::specialized);
// `scene` rendered in each of `modes` against one reference (the reference is
// most of a comparison's time: a spectral one sums every wavelength per pixel).
std::vector<Comparison> compare_gpu_modes_with_reference(const Scene& scene, const std::vector<ShaderMode>& modes);

// A scene with one sphere of `material` at the origin, the docs/spec.md#7-scene-files camera
// (perspective, or orthographic with height 2.5), and `lights`.
Scene single_sphere_scene(const Material& material, const std::vector<Light>& lights, bool orthographic);

Light directional(const dvec3& direction, double intensity = 1.0, const dvec3& color = dvec3(1.0));

// The process's one headless context and renderer (made on first use), which
// the comparisons above render with; a test that sets a renderer option
// (shader mode, blend) sets it back or sets it before each render.
Renderer& shared_renderer();
const GlApi& shared_gl();

}  // namespace m3055::test
