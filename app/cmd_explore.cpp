// `m3055 explore`: the interactive explorer (explore/ and explore_ui/), and plain `m3055`.
// Built with -DM3055_BUILD_EXPLORER=OFF (no GLFW, no ImGui), the subcommand is
// still there so that `m3055 explore ...` says in one line why it cannot open.
#include "commands.h"

#ifdef M3055_HAVE_EXPLORER
#include "explore_ui/explore.h"
#endif

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <iostream>
#include <memory>

namespace m3055 {

#ifdef M3055_HAVE_EXPLORER

void add_explore_command(CLI::App& app) {
    auto options = std::make_shared<ExploreOptions>();
    CLI::App* explore = app.add_subcommand(
        "explore", "Open the interactive explorer window (needs a display; see README)");
    CLI::Option* scene =
        explore->add_option("--scene", options->scene_path, "Scene JSON to start with (with --assignment it may be new: "
                            "the assignment's start scene, saved there)");
    // `explore --assignment A.json SCENE.json`: the scene as a positional argument too.
    explore->add_option("SCENE", options->scene_path, "Scene JSON to start with (as --scene)")->excludes(scene);
    explore->add_option("--assignment", options->assignment_path,
                        "Practise an assignment (docs/grading.md): its reference beside the display, the live "
                        "score and reasons m3055 grade would give")
        ->check(CLI::ExistingFile);
    explore->add_flag("--allow-brdf", options->allow_brdf,
                      "With --assignment: grade .brdf materials as m3055 grade --allow-brdf does (without it they "
                      "score 0, as grade gives them)");
    explore->add_option("--script", options->script_path,
                        "Text file of UI actions, one per frame (see explore/script.h)")
        ->check(CLI::ExistingFile);
    explore->add_flag("--exit-after-script", options->exit_after_script,
                      "Quit when the script has run (and the window capture is written)");
    explore->add_option("--capture-window", options->capture_window,
                        "Write a PNG of the whole window once the script is done");
    explore->add_option("--stats", options->stats_path,
                        "Write frame counts (total, and while idle) and start-up to the first frame (ms) as JSON at exit");
    explore->add_flag("--compile-at-once", options->compile_at_once,
                      "Compile a new shader specialization before drawing (stalls; the default draws with the "
                      "general program meanwhile, the same pixels)");
    explore->add_option("--window-size", [options](const CLI::results_t& r) {
                            options->window_width = std::stoi(r.at(0));
                            options->window_height = std::stoi(r.at(1));
                            return true;
                        }, "Window width and height in pixels (default: the screen's work area)")
        ->expected(2)->type_name("W H");
    explore->callback([options]() {
        const int status = run_explorer(*options);
        if (status != 0) throw CLI::RuntimeError(status);
    });
}

int run_without_subcommand(const CLI::App& app) {
    // Plain `m3055`: the explorer when there is a display to show it on.
    const char* display = std::getenv("DISPLAY");
    if (display && *display) return run_explorer(ExploreOptions{});
    std::cerr << app.help() << "\nm3055: no display ($DISPLAY is unset): use a subcommand, e.g. m3055 render\n";
    return kExitUsage;
}

#else  // built without the explorer

namespace {
constexpr const char* kNoExplorer =
    "m3055: this build has no explorer (configured with -DM3055_BUILD_EXPLORER=OFF): use m3055 render, "
    "or rebuild with scripts/setup, which installs GLFW and Dear ImGui";
}

void add_explore_command(CLI::App& app) {
    // No options and no --help of its own: whatever follows `explore` (scripts/run
    // probes `explore --help`) gets the one line and a failing exit status.
    CLI::App* explore = app.add_subcommand("explore", "Not in this build (configured with -DM3055_BUILD_EXPLORER=OFF)");
    explore->set_help_flag();
    explore->prefix_command();  // every later argument is an extra, never a parse error
    explore->callback([]() {
        std::cerr << kNoExplorer << "\n";
        throw CLI::RuntimeError(kExitFailure);
    });
}

int run_without_subcommand(const CLI::App& app) {
    std::cerr << app.help() << "\n" << kNoExplorer << "\n";
    return kExitUsage;
}

#endif

}  // namespace m3055
