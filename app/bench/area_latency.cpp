#include "area_latency.h"

#include "timing.h"
#include "explore/apply.h"
#include "explore/display_renderers.h"
#include "explore/files.h"
#include "explore/operations.h"
#include "explore/start.h"
#include "frame/renderer.h"
#include "gl/context.h"
#include "scene/load.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <functional>
#include <vector>

namespace m3055::bench {

namespace {

double drag_percentile(std::vector<double> samples, double p) {
    std::sort(samples.begin(), samples.end());
    const double at = p * double(samples.size() - 1);
    const std::size_t lo = std::size_t(std::floor(at)), hi = std::min(samples.size() - 1, lo + 1);
    return samples[lo] + (samples[hi] - samples[lo]) * (at - double(lo));
}

// The key's width slider dragged from 1.6 to 3.0 and back in `steps` steps,
// each timed from the edit to finished pixels; `frame` draws the displays.
std::vector<double> drag(explore::Explorer& explorer, const GlApi& gl, int steps,
                         const std::function<void()>& frame) {
    std::vector<double> samples;
    for (int i = 0; i < steps; ++i) {
        const double t = double(i) / double(steps - 1);
        Light key = explorer.doc.scene.lights[0];
        key.size[0] = 1.6 + 1.4 * std::sin(3.14159265358979 * t);
        samples.push_back(time_ms([&]() {
            explorer.commands.push(explore::command::SetLight{0, key});
            explore::apply_commands(explorer);
            frame();
            gl.Finish();
        }));
    }
    explore::commit_edits(explorer);
    return samples;
}

DragStats stats_of(const std::vector<double>& samples) {
    return {int(samples.size()), drag_percentile(samples, 0.5), drag_percentile(samples, 0.95),
            *std::max_element(samples.begin(), samples.end())};
}

}  // namespace

AreaLatencyReport area_light_latency(const BenchOptions& options) {
    const auto context = HeadlessContext::create(options.backend);
    const GlApi& gl = context->gl();
    const Scene scene = load_scene_file(find_scenes_dir(options.scenes) + "/softbox_three_point.json",
                                        LoadContext::trusted());
    Renderer a(gl), b(gl);  // as the explorer's panes: no stall on a specialization
    explore::defer_compiles(a);
    explore::Explorer explorer;
    explore::set_scene(explorer, scene, "softbox_three_point");
    explore::start_history(explorer);
    // Start-up (untimed): the scene's programs built, as after the explorer's first idle moment.
    explore::PreviewScale scale;
    scale.note(time_ms([&]() {
                   explore::render_displays(explorer, a, b);
                   gl.Finish();
               }),
               1);
    explore::refine_displays(explorer, a, b);
    gl.Finish();
    AreaLatencyReport report;
    report.device = context->renderer_string() + " via " + context->backend_name();
    // Before: every frame at the display's size, one sample an emitter and 2 x 2 shadow rays.
    report.before = stats_of(drag(explorer, gl, options.quick ? 3 : 8, [&]() {
        a.set_area_sampling({1, 2});
        a.render(explorer.doc.scene);
    }));
    // After: as the explorer's panes draw (app/explore_ui/display_panes.cpp).
    std::vector<int> divisors;
    report.after = stats_of(drag(explorer, gl, options.quick ? 10 : 60, [&]() {
        const int divisor = scale.divisor();
        divisors.push_back(divisor);
        const double ms = time_ms([&]() {
            explore::render_displays(explorer, a, b, divisor);
            gl.Finish();
        });
        scale.note(ms, divisor);
    }));
    report.divisor_min = *std::min_element(divisors.begin(), divisors.end());
    report.divisor_max = *std::max_element(divisors.begin(), divisors.end());
    // The refine's first pass (app/explore_ui/display_panes.cpp): the preview drawn smaller is
    // drawn whole at the display's size, then the render's pass.
    report.sharpen_ms = time_ms([&]() {
        explore::render_displays(explorer, a, b, 1);
        gl.Finish();
    });
    report.refine_ms = time_ms([&]() {
        explore::refine_displays(explorer, a, b);
        gl.Finish();
    });
    return report;
}

std::string AreaLatencyReport::markdown() const {
    std::string md = "## Explorer latency with area lights\n\n";
    md += "scenes/softbox_three_point.json (rect key with shadow, rect fill, disk back light), 512 x 320 x 5 "
          "bits; the key's width dragged, each step from the edit to finished pixels (render + glFinish) with the preview's sampling; then "
          "the display refined to the render's pixels (kRenderSampling); " + device + ".\n\n";
    md += "| frame while dragging | steps | p50 ms | p95 ms | max ms |\n|---|---|---|---|---|\n";
    char row[256];
    std::snprintf(row, sizeof row, "| before: the display's size, 2 x 2 shadow rays | %d | %.1f | %.1f | %.1f |\n",
                  before.steps, before.p50_ms, before.p95_ms, before.max_ms);
    md += row;
    std::snprintf(row, sizeof row, "| after: 1/%d to 1/%d of the size, 1 shadow ray | %d | %.1f | %.1f | %.1f |\n",
                  divisor_min, divisor_max, after.steps, after.p50_ms, after.p95_ms, after.max_ms);
    md += row;
    std::snprintf(row, sizeof row,
                  "\nOnce input stops, the preview at the display's size (the refine's first pass) in %.0f ms; "
                  "then refined to the render's pixels (8 x 8 samples, 8 x 8 rays) in %.0f ms.\n",
                  sharpen_ms, refine_ms);
    return md + row;
}

void run_area_latency(const BenchOptions& options) {
    const std::string md = area_light_latency(options).markdown();
    std::filesystem::create_directories(options.out);
    std::ofstream(options.out + "/area_latency.md") << md;
    std::cout << md;
}

}  // namespace m3055::bench
