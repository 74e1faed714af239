#include "latency.h"

#include "timing.h"
#include "explore/display_renderers.h"
#include "explore/files.h"
#include "explore/operations.h"
#include "explore/undo.h"
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

using Edit = std::function<void(explore::ExplorerState&)>;

// The session: what a student does in the explorer, one edit a step, at the
// default 512 x 320 x 5 bits, through the explorer's own operations
// (explore/operations.h: what the panels call).
std::vector<Edit> session() {
    using namespace explore;
    std::vector<Edit> steps;
    for (const ModelSpec& model : model_table().models())
        steps.push_back([name = model.name](ExplorerState& s) { set_model(s, name); });
    steps.push_back([](ExplorerState& s) { edit_material(s, Material::of("highlight")); });
    for (LightType type : {LightType::point, LightType::spot, LightType::directional}) {
        steps.push_back([type](ExplorerState& s) {
            Light light = s.scene.lights[0];
            light.type = type;
            light.position = {2.0, 2.0, 3.0};
            light.spot_direction = {-2.0, -2.0, -3.0};
            edit_light(s, 0, light);
        });
    }
    for (LightPreset preset : kAllLightPresets)
        steps.push_back([preset](ExplorerState& s) { apply_light_preset(s, preset); });
    for (int i = 1; i <= 3; ++i) {
        steps.push_back([i](ExplorerState& s) {  // "+ add sphere", then its model
            s.selected_object = 0;
            add_object(s, Shape::sphere);
            if (i == 2) edit_material(s, Material::of("translucent"));
            if (i == 3) edit_material(s, Material::of("metal"));
        });
    }
    for (int i = 0; i < 50; ++i) {  // a slider dragged: m (eq. 4) from 2 to 100
        steps.push_back([i](ExplorerState& s) {
            s.selected_object = 0;
            Material m = s.scene.objects[0].material;
            m.set_number("m", 2.0 + 98.0 * i / 49.0);
            edit_material(s, m);
        });
    }
    return steps;
}

double percentile(std::vector<double> samples, double p) {
    std::sort(samples.begin(), samples.end());
    const double at = p * double(samples.size() - 1);
    const std::size_t lo = std::size_t(std::floor(at)), hi = std::min(samples.size() - 1, lo + 1);
    return samples[lo] + (samples[hi] - samples[lo]) * (at - double(lo));
}

// The explorer's frame, timed: the edit, then A drawn (explore/display_renderers.h
// render_displays, B only in the split) and finished. Between steps, the
// explorer's idle rule (render_specialized_when_idle) as the explorer runs it
// after kIdleBeforeCompile s without input.
LatencyStats run_session(const GlApi& gl, bool defer) {
    Renderer a(gl), b(gl);  // B stays idle: the session has no A/B split
    if (defer) explore::defer_compiles(a);
    explore::ExplorerState state;  // as `m3055 explore` starts
    explore::set_scene(state, default_scene(), "spec example");
    explore::start_history(state);
    // Start-up (not a step): the first scene's programs.
    explore::render_displays(state, a, b);
    if (defer) explore::render_specialized_when_idle(state, a, b);
    gl.Finish();
    LatencyStats stats;
    std::vector<double> samples;
    for (const Edit& edit : session()) {
        const std::size_t programs = a.compiled_programs();
        samples.push_back(time_ms([&]() {
            edit(state);
            explore::render_displays(state, a, b);
            gl.Finish();
        }));
        stats.compiles_in_steps += int(a.compiled_programs() - programs);
        explore::commit_edits(state);  // the step ends (untimed: the frame loop does it after drawing)
        if (explore::deferred_programs(a, b) > 0) {
            const std::size_t before = a.compiled_programs();
            const double ms = time_ms([&]() {
                explore::render_specialized_when_idle(state, a, b);
                gl.Finish();
            });
            stats.compiles_when_idle += int(a.compiled_programs() - before);
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
    std::string md = "## Explorer latency\n\n";
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
