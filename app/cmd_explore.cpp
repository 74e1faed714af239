// `m3055 explore`: the interactive explorer (app/explore/).
#include "explore/explore.h"

#include <CLI/CLI.hpp>

#include <memory>

namespace m3055 {

void add_explore_command(CLI::App& app) {
    auto options = std::make_shared<ExploreOptions>();
    CLI::App* explore = app.add_subcommand(
        "explore", "Open the interactive explorer window (needs a display; see README)");
    explore->add_option("--scene", options->scene_path, "Scene JSON to start with")->check(CLI::ExistingFile);
    explore->add_option("--script", options->script_path,
                        "Text file of UI actions, one per frame (see app/explore/script.h)")
        ->check(CLI::ExistingFile);
    explore->add_flag("--exit-after-script", options->exit_after_script,
                      "Quit when the script has run (and the window capture is written)");
    explore->add_option("--capture-window", options->capture_window,
                        "Write a PNG of the whole window once the script is done");
    explore->add_option("--stats", options->stats_path,
                        "Write frame counts (total, and while idle) as JSON at exit");
    explore->add_option("--window-size", [options](const CLI::results_t& r) {
                            options->window_width = std::stoi(r.at(0));
                            options->window_height = std::stoi(r.at(1));
                            return true;
                        }, "Window width and height in pixels (default 1500 940)")
        ->expected(2)->type_name("W H");
    explore->callback([options]() {
        const int status = run_explorer(*options);
        if (status != 0) throw CLI::RuntimeError(status);
    });
}

}  // namespace m3055
