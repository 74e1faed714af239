#include "latency.h"

#include "timing.h"
#include "models/model_table.h"
#include "frame/renderer.h"
#include "models/material.h"
#include "scene/presets.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <vector>

namespace m3055::bench {

namespace {

using Edit = std::function<void(Scene&)>;

// The session: what a student does in the explorer, one edit a step, at the
// default 512 x 320 x 5 bits.
std::vector<Edit> session() {
    std::vector<Edit> steps;
    for (const ModelSpec& model : model_table().models())
        steps.push_back([&model](Scene& s) { s.objects[0].material = with_model(s.objects[0].material, model); });
    steps.push_back([](Scene& s) { s.objects[0].material = Material::of("highlight"); });
    for (LightType type : {LightType::point, LightType::spot, LightType::directional}) {
        steps.push_back([type](Scene& s) {
            Light& light = s.lights[0];
            light.type = type;
            light.position = {2.0, 2.0, 3.0};
            light.spot_direction = {-2.0, -2.0, -3.0};
        });
    }
    for (LightPreset preset : kAllLightPresets) steps.push_back([preset](Scene& s) { s.lights = light_preset(preset); });
    for (int i = 1; i <= 3; ++i) {
        steps.push_back([i](Scene& s) {
            Object sphere = s.objects[0];
            sphere.center = {2.2 * i, 0.0, 0.0};
            sphere.radius = 0.8;
            if (i == 2) sphere.material = Material::of("translucent");
            if (i == 3) sphere.material = Material::of("metal");
            s.objects.push_back(sphere);
        });
    }
    for (int i = 0; i < 50; ++i)  // a slider dragged: m (eq. 4) from 2 to 100
        steps.push_back([i](Scene& s) { s.objects[0].material.set_number("m", 2.0 + 98.0 * i / 49.0); });
    return steps;
}

double percentile(std::vector<double> samples, double p) {
    std::sort(samples.begin(), samples.end());
    const double at = p * double(samples.size() - 1);
    const std::size_t lo = std::size_t(std::floor(at)), hi = std::min(samples.size() - 1, lo + 1);
    return samples[lo] + (samples[hi] - samples[lo]) * (at - double(lo));
}

LatencyStats run_session(const GlApi& gl, bool defer) {
    Renderer renderer(gl);
    renderer.set_defer_compiles(defer);
    Scene scene = default_scene();
    // Start-up (not a step): the first scene's programs, and the general ones.
    if (defer) renderer.warm_up_general_programs();
    renderer.render(scene);
    if (defer) renderer.render_specialized(scene);
    gl.Finish();
    LatencyStats stats;
    std::vector<double> samples;
    for (const Edit& edit : session()) {
        const std::size_t programs = renderer.compiled_programs();
        samples.push_back(time_ms([&]() {
            edit(scene);
            renderer.render(scene);
            gl.Finish();
        }));
        stats.compiles_in_steps += int(renderer.compiled_programs() - programs);
        // The pause before the next input: the explorer draws the scene with
        // its specialized programs then (app/explore/explore.cpp compile_when_idle).
        if (renderer.deferred_programs() > 0) {
            const std::size_t before = renderer.compiled_programs();
            const double ms = time_ms([&]() {
                renderer.render_specialized(scene);
                gl.Finish();
            });
            stats.compiles_when_idle += int(renderer.compiled_programs() - before);
            stats.max_idle_compile_ms = std::max(stats.max_idle_compile_ms, ms);
        }
    }
    stats.steps = int(samples.size());
    stats.p50_ms = percentile(samples, 0.50);
    stats.p95_ms = percentile(samples, 0.95);
    stats.max_ms = *std::max_element(samples.begin(), samples.end());
    return stats;
}

}  // namespace

LatencyReport explorer_latency(Backend backend) {
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    const auto context = HeadlessContext::create(backend);
    LatencyReport report;
    report.device = context->renderer_string() + " via " + context->backend_name();
    report.before = run_session(context->gl(), false);
    report.after = run_session(context->gl(), true);
    return report;
}

std::string LatencyReport::markdown() const {
    std::string md = "## Explorer latency (issue 12)\n\n";
    md += "Edit to finished pixels (render + glFinish) per step of a scripted session: every model, every light "
          "type and preset, 3 object additions, 50 slider moves; 512 x 320 x 5 bits; " + device +
          "; Mesa's shader cache off.\n\n";
    md += "| | steps | p50 ms | p95 ms | max ms | compiles in a step | compiles when idle | longest idle compile ms |\n";
    md += "|---|---|---|---|---|---|---|---|\n";
    char row[256];
    for (const auto& [name, s] : {std::pair{"before: compile, then draw", &before},
                                  std::pair{"after: general program, compile when idle", &after}}) {
        std::snprintf(row, sizeof row, "| %s | %d | %.1f | %.1f | %.1f | %d | %d | %.1f |\n", name, s->steps, s->p50_ms,
                      s->p95_ms, s->max_ms, s->compiles_in_steps, s->compiles_when_idle, s->max_idle_compile_ms);
        md += row;
    }
    md += "\nAfter: an input that arrives while an idle compile runs waits for it (the last column).\n";
    return md;
}

}  // namespace m3055::bench
