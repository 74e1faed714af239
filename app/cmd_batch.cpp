// `m3055 batch MANIFEST.json`: renders many scenes in one process, reusing the
// context and compiled programs (issue 4). Each output is byte-identical to
// `m3055 render` of that scene: both go through Capture::render_to_files.
#include "batch.h"
#include "commands.h"
#include "interrupt.h"
#include "progress.h"

#include <unistd.h>

#include <iostream>

namespace m3055 {

void add_batch_command(CLI::App& app) {
    struct Options {
        std::string manifest, backend = "auto";
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("batch", "Render every scene of a manifest in one process");
    command->add_option("manifest", options->manifest,
                        "JSON array of {\"scene\": \"a.json\", \"out\": \"a.png\", \"raw\": \"a.pfm\"}; "
                        "paths relative to the manifest's folder")
        ->required();
    command->add_option("--backend", options->backend, "GL context: auto (EGL, then OSMesa), egl or osmesa")
        ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
    command->callback([options]() {
        std::size_t failures = 0, total = 0, written = 0;
        // Ctrl-C stops between scenes: finished files kept, none half-written.
        const InterruptWatch interrupt;
        try {
            const std::vector<BatchItem> items = load_manifest(options->manifest);
            total = items.size();
            Capture capture(parse_backend(options->backend));
            Progress progress(items.size(), isatty(STDERR_FILENO) == 1);
            failures = run_batch(
                capture, items,
                [&](std::size_t, const BatchItem& item, const std::string& error) {
                    progress.step(item.out, error);
                    if (error.empty()) ++written;
                },
                0, [&]() { return interrupt.raised(); });
            progress.finish();
        } catch (const std::exception& error) {
            std::cerr << "m3055: " << error.what() << "\n";
            throw CLI::RuntimeError(kExitFailure);
        }
        if (interrupt.raised()) {
            std::cerr << "m3055: interrupted by " << signal_name(interrupt.signal()) << ": " << written << " of "
                      << total << " scenes written, the rest not started\n";
            throw CLI::RuntimeError(kExitInterrupted);
        }
        if (failures) {
            std::cerr << "m3055: " << failures << " of " << total << " scenes failed\n";
            throw CLI::RuntimeError(kExitFailure);
        }
    });
}

}  // namespace m3055
