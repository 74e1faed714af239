// `m3055 batch MANIFEST.json`: renders many scenes in one process, reusing the
// context and compiled programs (issue 4). Each output is byte-identical to
// `m3055 render` of that scene: both go through Capture::render_to_files.
#include "batch.h"
#include "commands.h"
#include "interrupt.h"
#include "progress.h"
#include "scene/json_brdf.h"

#include <unistd.h>

#include <atomic>
#include <iostream>
#include <memory>

namespace m3055 {

// The default time budget of one scene in a batch: a class's worth of scenes
// must not be held up by one (docs/limits.md: the slowest legal scene
// measured, 8192 x 8192 or 100 000 spheres, draws in under 6 s here).
constexpr double kBatchSceneTimeout = 30;

void add_batch_command(CLI::App& app) {
    struct Options {
        std::string manifest, backend = "auto";
        double scene_timeout = kBatchSceneTimeout;
        bool allow_brdf = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("batch", "Render every scene of a manifest in one process");
    command->add_option("manifest", options->manifest,
                        "JSON array of {\"scene\": \"a.json\", \"out\": \"a.png\", \"raw\": \"a.pfm\"}; "
                        "paths relative to the manifest's folder")
        ->required();
    command->add_option("--backend", options->backend, "GL context: auto (EGL, then OSMesa), egl or osmesa")
        ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
    command->add_option("--scene-timeout", options->scene_timeout,
                        "Skip a scene not drawn within SECONDS of starting to load it (0: no limit)")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    command->add_flag("--allow-brdf", options->allow_brdf,
                      "Accept materials from .brdf files (their shader code runs; off: a scene with one is an error)");
    command->callback([options]() {
        // A .brdf file is code: a class's scenes run it only when asked to.
        scene_json::set_brdf_files_allowed(options->allow_brdf);
        std::atomic<std::size_t> total{0}, written{0};
        // SIGINT, SIGTERM, SIGHUP: wherever the batch is, temporaries removed,
        // finished files kept, one line, ended by the signal.
        const bool interactive = isatty(STDERR_FILENO) == 1;
        const InterruptGuard interrupt([&](int signal) {
            // On a terminal the progress bar's line is cleared first.
            return std::string(interactive ? "\r\033[K" : "") +
                   error_line("interrupted by " + signal_name(signal) + ": " + std::to_string(written.load()) + " of " +
                              std::to_string(total.load()) + " scenes written, the rest not");
        });
        std::size_t failures = 0;
        try {
            std::vector<BatchItem> items = load_manifest(options->manifest);
            check_batch_files(items, options->manifest);
            total = items.size();
            // Made when the first scene is drawn: a batch of broken scenes never needs one.
            std::unique_ptr<Capture> capture;
            const Backend backend = parse_backend(options->backend);
            const auto make_capture = [&]() -> Capture& {
                if (!capture) capture = std::make_unique<Capture>(backend);
                return *capture;
            };
            Progress progress(items.size(), interactive);
            BatchOptions batch;
            batch.on_written = [&] { ++written; };
            batch.scene_timeout_s = options->scene_timeout;
            failures = run_batch(
                make_capture, items,
                [&](std::size_t, const BatchItem& item, const std::string& error) { progress.step(item.out, error); },
                batch);
            progress.finish();
        } catch (const std::exception& error) {
            std::cerr << error_text(error) << "\n";
            throw CLI::RuntimeError(kExitFailure);
        }
        if (failures) {
            std::cerr << "m3055: " << failures << " of " << total << " scenes failed\n";
            throw CLI::RuntimeError(kExitFailure);
        }
    });
}

}  // namespace m3055
