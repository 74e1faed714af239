// GPU evaluation harness for the numerical stress test (tests/stress_test.cpp):
// renders ONE INPUT PER PIXEL with glsl/passes/stress.frag (the real model
// code of glsl/models/) into RGBA32F targets, and evaluates the same inputs
// with the double-precision reference (renderer/reference/).
//
// Light 0 of every batch is a point light at the origin with attenuation
// (1, 0, 0) (factor exactly 1), and each pixel sits at P = -L_raw: so every
// pixel gets its own light direction L_raw / |L_raw| through the real
// light_sample / ref::sample_light. Further lights (directional, fixed per
// batch) may follow.
#pragma once

#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace m3055::test {

// One evaluation. The directions are raw (any non-zero length) and are the
// exact float values the GPU reads; the material's numbers must be floats
// already (use float_rounded) so that GPU and reference see the same input.
struct StressInput {
    glm::vec3 N{0.f, 0.f, 1.f};
    glm::vec3 V{0.f, 0.f, 1.f};  // towards the viewer
    glm::vec3 L{0.f, 0.f, 1.f};  // towards light 0
    Material material;
};

// What a model gives: opaque models write `color` (transmittance 0);
// translucent writes the premultiplied colour and the transmittance (docs/spec.md#42-translucent).
struct StressOutput {
    dvec3 color{0.0};
    dvec3 transmittance{0.0};
};

struct StressBatch {
    std::vector<StressInput> inputs;
    Light light0;                   // type, position and attenuation are overwritten (see above)
    std::vector<Light> more_lights;  // fixed for the batch
};

// The lights the batch really uses (light0 made a point light at the origin).
std::vector<Light> stress_lights(const StressBatch& batch);

// `material` with every number rounded to float, as the GPU receives it.
Material float_rounded(Material material);

class StressHarness {
public:
    StressHarness();  // headless context + the stress program; throws on failure
    ~StressHarness();
    StressHarness(const StressHarness&) = delete;
    StressHarness& operator=(const StressHarness&) = delete;

    // Renders the batch, `width` inputs per row (the last row padded), and
    // returns one output per input, in input order.
    std::vector<StressOutput> evaluate_gpu(const StressBatch& batch, int width = 1024);

    std::string renderer_string() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// The double-precision reference on exactly the GPU's input (directions
// widened from float and normalized in double).
StressOutput evaluate_reference(const StressInput& input, const std::vector<Light>& lights);

}  // namespace m3055::test
