#include "latency.h"

#include "timing.h"
#include "explore/apply.h"
#include "explore/display_renderers.h"
#include "explore/files.h"
#include "explore/operations.h"
#include "explore/start.h"
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

using Step = std::function<void(explore::Explorer&)>;

// The session: what a student does in the explorer, one edit a step, at the
// default 512 x 320 x 5 bits, as the commands the panels give (explore/commands.h).
std::vector<Step> session() {
    using namespace explore;
    std::vector<Step> steps;
    auto material = [](Explorer& e, Material m) { e.commands.push(command::SetMaterial{e.view.selected_object, std::move(m), ""}); };
    for (const ModelSpec& model : model_table().models())
        steps.push_back([name = model.name, material](Explorer& e) { material(e, with_model_named(*selected_material(e), name)); });
    steps.push_back([material](Explorer& e) { material(e, Material::of("highlight")); });
    for (LightType type : {LightType::point, LightType::spot, LightType::directional}) {
        steps.push_back([type](Explorer& e) {
            Light light = e.doc.scene.lights[0];
            light.type = type;
            light.position = {2.0, 2.0, 3.0};
            light.spot_direction = {-2.0, -2.0, -3.0};
            e.commands.push(command::SetLight{0, light});
        });
    }
    for (LightPreset preset : kAllLightPresets)
        steps.push_back([preset](Explorer& e) { e.commands.push(command::ApplyLightPreset{preset}); });
    for (int i = 1; i <= 3; ++i) {
        steps.push_back([i, material](Explorer& e) {  // "+ add sphere", then its model
            e.view.selected_object = 0;
            run_command(e, command::AddObject{Shape::sphere});
            if (i == 2) material(e, Material::of("translucent"));
            if (i == 3) material(e, Material::of("metal"));
        });
    }
    for (int i = 0; i < 50; ++i) {  // a slider dragged: m (eq. 4) from 2 to 100
        steps.push_back([i, material](Explorer& e) {
            e.view.selected_object = 0;
            Material m = e.doc.scene.objects[0].material;
            m.set_number("m", 2.0 + 98.0 * i / 49.0);
            material(e, m);
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
    explore::Explorer explorer;  // as `m3055 explore` starts
    explore::set_scene(explorer, default_scene(), "spec example");
    explore::start_history(explorer);
    // Start-up (not a step): the first scene's programs.
    explore::render_displays(explorer, a, b);
    if (defer) explore::render_specialized_when_idle(explorer, a, b);
    gl.Finish();
    LatencyStats stats;
    std::vector<double> samples;
    for (const Step& step : session()) {
        const std::size_t programs = a.compiled_programs();
        samples.push_back(time_ms([&]() {
            step(explorer);
            explore::apply_commands(explorer);
            explore::render_displays(explorer, a, b);
            gl.Finish();
        }));
        stats.compiles_in_steps += int(a.compiled_programs() - programs);
        explore::commit_edits(explorer);  // the step ends (untimed: the frame loop does it after drawing)
        if (explore::deferred_programs(a, b) > 0) {
            const std::size_t before = a.compiled_programs();
            const double ms = time_ms([&]() {
                explore::render_specialized_when_idle(explorer, a, b);
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
