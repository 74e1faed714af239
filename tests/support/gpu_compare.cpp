#include "gpu_compare.h"

#include "sanitized.h"

#include "gl/context.h"
#include "image/quantize.h"
#include "reference/reference.h"
#include "frame/renderer.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

namespace m3055::test {

namespace {

struct Gpu {
    std::unique_ptr<HeadlessContext> context = HeadlessContext::create(Backend::automatic);
    Renderer renderer{context->gl()};
};

Gpu& gpu() {
    static Gpu instance;
    return instance;
}

}  // namespace

Renderer& shared_renderer() { return gpu().renderer; }
const GlApi& shared_gl() { return gpu().context->gl(); }

std::string Comparison::describe() const {
    std::ostringstream text;
    text << "interior pixels " << interior_pixels << ", max |diff| " << max_abs_diff << ", max scaled diff "
         << max_scaled_diff << ", mean |diff| " << mean_abs_diff << ", mean diff " << mean_signed_diff << ", same level " << same_level_share * 100
         << "%, max level diff " << max_level_diff << ", non-finite " << nonfinite_values;
    return text.str();
}

Comparison compare_gpu_with_reference(const Scene& scene, ShaderMode mode) {
    return compare_gpu_with_reference_of(scene, scene, mode);
}

namespace {

// How far the GPU's raw (unquantized, bottom-up) output is from the reference
// on the reference's interior pixels.
Comparison compare_raw(const RgbFloatImage& raw, const ref::ReferenceImage& reference, const Display& display) {
    const int w = display.width, h = display.height, bits = display.bits;
    const bool srgb = display.view_transform == ViewTransform::srgb;
    Comparison result;
    long same = 0;
    double sum = 0, signed_sum = 0;
    for (float value : raw.pixels)
        if (!std::isfinite(value)) ++result.nonfinite_values;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (!ref::is_interior(reference, x, y)) continue;
            ++result.interior_pixels;
            bool same_level = true;
            for (int c = 0; c < 3; ++c) {
                const double expected = reference.rgb[(std::size_t(y) * w + x) * 3 + c];
                const double actual = raw.pixels[(std::size_t(h - 1 - y) * w + x) * 3 + c];  // raw is bottom-up
                const double diff = std::abs(actual - expected);
                result.max_abs_diff = std::max(result.max_abs_diff, diff);
                result.max_scaled_diff = std::max(result.max_scaled_diff, diff / std::max(1.0, std::abs(expected)));
                sum += diff;
                signed_sum += actual - expected;
                const int level_diff = std::abs(quantize_level(actual, bits, srgb) - quantize_level(expected, bits, srgb));
                result.max_level_diff = std::max(result.max_level_diff, level_diff);
                if (level_diff) same_level = false;
            }
            if (same_level) ++same;
        }
    }
    if (result.interior_pixels) {
        result.mean_abs_diff = sum / (3.0 * result.interior_pixels);
        result.mean_signed_diff = signed_sum / (3.0 * result.interior_pixels);
        result.same_level_share = double(same) / result.interior_pixels;
    } else {
        result.same_level_share = 1.0;
    }
    return result;
}

RgbFloatImage render_raw(const Scene& scene, ShaderMode mode) {
    Gpu& g = gpu();
    g.renderer.set_shader_mode(mode);
    g.renderer.render(scene);
    return g.renderer.read_raw();
}

}  // namespace

Comparison compare_gpu_with(const Scene& scene, const ref::ReferenceImage& reference, ShaderMode mode) {
    return compare_raw(render_raw(scene, mode), reference, scene.display);
}

Comparison compare_gpu_with_reference_of(const Scene& scene, const Scene& reference_scene, ShaderMode mode) {
    return compare_gpu_with(scene, ref::render_reference(reference_scene), mode);
}

std::vector<Comparison> compare_gpu_modes_with_reference(const Scene& scene, const std::vector<ShaderMode>& modes) {
    const ref::ReferenceImage reference = ref::render_reference(scene);
    std::vector<Comparison> results;
    for (ShaderMode mode : modes) results.push_back(compare_gpu_with(scene, reference, mode));
    return results;
}

Scene single_sphere_scene(const Material& material, const std::vector<Light>& lights, bool orthographic) {
    Scene scene;
    scene.camera.position = {0, 0, 4.5};
    scene.camera.target = {0, 0, 0};
    scene.camera.up = {0, 1, 0};
    if (orthographic) {
        scene.camera.projection = Projection::orthographic;
        scene.camera.height = 2.5;
    } else {
        scene.camera.projection = Projection::perspective;
        scene.camera.fov_y_deg = 30;
    }
    // Under the sanitizers a quarter of the pixels, 256 x 160: the same code
    // runs for every pixel, and the instrumented reference shading every pixel
    // in double precision was most of the GPU-against-reference suites' time
    // there. The Release suite compares at the M3055's 512 x 320.
    if (kSanitized) scene.display.width = 256, scene.display.height = 160;
    scene.lights = lights;
    Object sphere;
    sphere.center = {0, 0, 0};
    sphere.radius = 1.0;
    sphere.material = material;
    scene.objects.push_back(sphere);
    return scene;
}

Light directional(const dvec3& direction, double intensity, const dvec3& color) {
    Light light;
    light.type = LightType::directional;
    light.direction = glm::normalize(direction);
    light.intensity = intensity;
    light.color = color;
    return light;
}

}  // namespace m3055::test
