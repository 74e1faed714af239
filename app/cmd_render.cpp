// `m3055 render`: one scene to PNG (and PFM), headless (docs/spec.md#8-command-line).
#include "commands.h"
#include "exit_now.h"
#include "headless_context.h"
#include "interrupt.h"
#include "progress.h"
#include "slow_note.h"

#include "analysis/nonfinite.h"
#include "analysis/reference_images.h"
#include "brdf_file/brdf_model.h"
#include "capture/capture.h"
#include "gl/program.h"
#include "io/message_text.h"
#include "io/run_files.h"
#include "reference/reference.h"
#include "scene/load.h"

#include <atomic>
#include <chrono>
#include <iostream>
#include <optional>

#include <unistd.h>

namespace m3055 {

void add_render_command(CLI::App& app) {
    struct Options {
        std::string scene, out, raw, backend = "auto", view_transform;
        std::vector<std::string> sets;
        double scene_timeout = 0;
        bool reference = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("render", "Render a scene headless to PNG (and PFM)");
    command->add_option("--scene", options->scene, "Scene JSON file (docs/spec.md#7-scene-files)")->required();
    command->add_option("--out", options->out, "Output PNG (8-bit RGB, quantized to display.bits)")->required();
    command->add_option("--raw", options->raw, "Also write the unquantized linear colour as PFM");
    CLI::Option* backend =
        command->add_option("--backend", options->backend, "GL context: auto (EGL, then OSMesa), egl or osmesa")
            ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
    command->add_option("--set", options->sets, "Override a scene value: path=value, e.g. objects[0].material.m=40");
    command->add_option("--view-transform", options->view_transform,
                        "What the display does before its levels: none (the scene's own, by default: the M3055 "
                        "shows levels of the linear value) or srgb (sRGB's encoding, as other tools show colour); "
                        "as the scene's display.view_transform")
        ->check(CLI::IsMember({"none", "srgb"}));
    CLI::Option* reference =
        command->add_flag("--reference", options->reference,
                          "Draw the double-precision CPU reference instead of the GPU's image: the exact answer the "
                          "GPU is tested against (docs/reference.md); the same levels and PFM, seconds to minutes "
                          "for area lights and shadows (on a terminal a line counts its rows); no GL context");
    CLI::Option* timeout =
        command->add_option("--scene-timeout", options->scene_timeout,
                            "Give up on a scene not drawn within SECONDS of starting to load it (default 0: no limit)")
            ->check(CLI::NonNegativeNumber);
    // The reference has no GL context to choose and no time budget.
    reference->excludes(backend)->excludes(timeout);
    command->callback([options]() {
        // SIGINT, SIGTERM, SIGHUP: temporaries removed, one line, ended by the signal.
        std::atomic<bool> written{false};
        const InterruptGuard interrupt([&](int signal) {
            const std::string files = text::quote_name(options->out) +
                                      (options->raw.empty() ? "" : " and " + text::quote_name(options->raw));
            return error_line("interrupted by " + signal_name(signal) + ": " +
                              (written ? files + " already written" : "nothing written"));
        });
        // A --set that is not PATH=VALUE is a mistake on the command line (exit 2).
        std::vector<Override> overrides;
        try {
            for (const auto& text : options->sets) overrides.push_back(parse_override(text));
        } catch (const SceneError& error) {
            std::cerr << error_text(error) << "\n";
            throw CLI::RuntimeError(kExitUsage);
        }
        try {
            // Before anything is read or written: no output may be the scene or the other output.
            io::RunFiles files;
            files.add_input(0, "--scene", options->scene);
            files.add_output(0, "--out", options->out);
            if (!options->raw.empty()) files.add_output(0, "--raw", options->raw);
            if (const auto problems = files.check(); !problems.empty()) throw std::runtime_error(problems.begin()->second);
            const auto start = std::chrono::steady_clock::now();
            Scene scene = load_scene_file(options->scene, LoadContext::trusted(), overrides);
            if (!options->view_transform.empty())
                scene.display.view_transform = options->view_transform == "srgb" ? ViewTransform::srgb : ViewTransform::none;
            if (options->reference) {
                // .brdf files' models have no C++ twin: their pixels would be NaN.
                for (std::size_t k = 0; k < scene.objects.size(); ++k)
                    if (find_brdf_model(scene.objects[k].material.model()))
                        throw std::runtime_error(text::quote_name(options->scene) + ": objects[" + std::to_string(k) +
                                                 "].material: a .brdf file's model has no CPU reference "
                                                 "(docs/reference.md); nothing written");
                // On a terminal, a line that counts the rows (a 512 x 320 scene with area
                // lights and shadows takes minutes); nothing in a log.
                std::optional<Progress> rows;
                if (isatty(STDERR_FILENO) == 1) rows.emplace(std::size_t(scene.display.height), true);
                const ref::ReferenceImage image = ref::render_reference(scene, ref::AreaQuadrature{}, nullptr, [&] {
                    if (rows) rows->step("", "");
                });
                if (rows) rows->finish();
                write_capture_files(options->out, reference_display(image, scene.display), options->raw,
                                    reference_raw(image), [&] { written = true; });
                exit_now(kExitOk);
            }
            const auto loaded = std::chrono::steady_clock::now();
            Capture capture(make_headless_context(parse_backend(options->backend)));
            // The budget covers loading and drawing, not making the GL context.
            capture.renderer().set_deadline(
                scene_deadline(start + (std::chrono::steady_clock::now() - loaded), options->scene_timeout));
            NonFinite nonfinite;
            // The raw image is read back for the count only where a .brdf material can make NaN (as batch does).
            NonFinite* counted = may_render_nonfinite(scene) ? &nonfinite : nullptr;
            try {
                SlowNote note = drawing_note("drawing");
                capture.render_to_files(scene, options->out, options->raw, [&] { written = true; }, counted);
                note.finished();
            } catch (const RenderTimeout&) {
                throw std::runtime_error(over_budget_message(options->scene, options->scene_timeout) +
                                         "; nothing written");
            }
            // Written all the same (exit 0): the warning says what the PNG's levels there mean.
            if (nonfinite.pixels > 0) std::cerr << nonfinite_warning(options->scene, nonfinite) << "\n";
            exit_now(kExitOk);  // the context, its threads and memory are left to the OS
        } catch (const std::exception& error) {
            std::cerr << error_text(error) << "\n";
            throw CLI::RuntimeError(kExitFailure);
        }
    });
}

}  // namespace m3055
