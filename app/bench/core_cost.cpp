#include "core_cost.h"

#include "timing.h"
#include "explore/apply.h"
#include "explore/brdf_files.h"
#include "explore/busy.h"
#include "explore/edits.h"
#include "explore/files.h"
#include "explore/operations.h"
#include "explore/start.h"
#include "scene/presets.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace m3055::bench {

namespace {

// The spec example with `count` spheres in a grid (the first as it was).
explore::Explorer explorer_with(int count) {
    Scene scene = default_scene();
    const Object first = scene.objects[0];
    scene.objects.clear();
    const int side = int(std::ceil(std::sqrt(double(count))));
    for (int i = 0; i < count; ++i) {
        Object sphere = first;
        sphere.radius = 0.4 / side;
        sphere.center = {-1.0 + 2.0 * (i % side + 0.5) / side, -1.0 + 2.0 * (i / side + 0.5) / side, 0.0};
        scene.objects.push_back(sphere);
    }
    explore::Explorer explorer;
    explore::set_scene(explorer, scene, "bench");
    explore::start_history(explorer);
    return explorer;
}

double median(std::vector<double> samples) {
    std::sort(samples.begin(), samples.end());
    return samples[samples.size() / 2];
}

CoreCost measure_core(int count) {
    using namespace explore;
    Explorer e = explorer_with(count);
    CoreCost cost;
    cost.objects = count;
    std::vector<double> ticks, frames, commits, undos;
    // What the frame loop's logic does in a frame with no input.
    auto idle_frame = [&e] {
        apply_commands(e);
        commit_edits(e);
        const std::string title = title_name(e.doc);
        e.session.busy = busy_line(e.session.brdf_watch, 0);
        return title.size() + watched_brdf_files(e).size();
    };
    for (int round = 0; round < 20; ++round) {
        for (int i = 0; i < 25; ++i) {  // a drag of 25 ticks on object 0's m
            Material m = e.doc.scene.objects[0].material;
            m.set_number("m", 2.0 + round + 0.01 * i);
            ticks.push_back(1e3 * time_ms([&] {
                e.commands.push(command::SetMaterial{0, std::move(m), ""});
                apply_commands(e);
            }));
        }
        commits.push_back(1e3 * time_ms([&] { commit_edits(e); }));
        for (int i = 0; i < 25; ++i) frames.push_back(1e3 * time_ms([&] { (void)idle_frame(); }));
    }
    for (int i = 0; i < 20; ++i) undos.push_back(1e3 * time_ms([&] { run_command(e, command::Undo{}); }));
    cost.tick_us = median(ticks);
    cost.frame_us = median(frames);
    cost.commit_us = median(commits);
    cost.undo_us = median(undos);
    return cost;
}

}  // namespace

CoreCostReport explorer_core_cost() {
    CoreCostReport report;
    for (int count : {10, 1000, 100000}) report.rows.push_back(measure_core(count));
    return report;
}

std::string CoreCostReport::markdown() const {
    std::string md = "## Explorer core: a slider tick and an idle frame against the scene's size\n\n";
    md += "The explorer's logic alone (no drawing): a tick is one slider value given as a command and applied "
          "(a typed edit, named, merged into the drag); an idle frame applies an empty queue, commits nothing and "
          "makes the title; medians over 500 each.\n\n";
    md += "| objects | tick us | idle frame us | end of drag (undo step) us | undo us |\n|---|---|---|---|---|\n";
    char row[160];
    for (const CoreCost& c : rows) {
        std::snprintf(row, sizeof row, "| %d | %.2f | %.2f | %.2f | %.2f |\n", c.objects, c.tick_us, c.frame_us,
                      c.commit_us, c.undo_us);
        md += row;
    }
    return md;
}

}  // namespace m3055::bench
