// `m3055 batch MANIFEST.json`: renders many scenes in one process, reusing the
// context and compiled programs. Each output is byte-identical to
// `m3055 render` of that scene: both go through Capture::render_to_files.
// `m3055 batch --out DIR SCENES...`: scene files, folders or glob
// patterns instead of a manifest, outputs named after the scenes;
// `--report FILE.json` and `--shard K/N` for class-sized runs.
#include "commands.h"
#include "headless_context.h"
#include "interrupt.h"
#include "progress.h"

#include "batch/run_batch.h"
#include "batch/scene_inputs.h"
#include "gl/program.h"
#include "gl/shader_cache.h"
#include "scene/load_context.h"

#include "grading/submissions.h"
#include "image/image.h"
#include "image/temporary_files.h"
#include "io/message_text.h"

#include <nlohmann/json.hpp>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>

namespace m3055 {

// The default time budget of one scene in a batch: a class's worth of scenes
// must not be held up by one (docs/limits.md: the slowest legal scene
// measured, 8192 x 8192 or 100 000 spheres, draws in under 6 s here).
constexpr double kBatchSceneTimeout = 30;

namespace {

struct BatchCommandOptions {
    std::vector<std::string> inputs;
    std::string backend = "auto", out_dir, report, shard = "1/1";
    bool raw = false;
    double scene_timeout = kBatchSceneTimeout;
    bool allow_brdf = false;
};

// The items to render: the manifest's, or one per scene input named into --out.
std::vector<BatchItem> batch_items(const BatchCommandOptions& options, std::string& manifest) {
    std::vector<BatchItem> items;
    if (options.out_dir.empty()) {
        if (options.inputs.size() != 1)
            throw std::runtime_error("batch: give one MANIFEST.json, or scenes, folders or patterns with --out DIR");
        manifest = options.inputs[0];
        items = load_manifest(manifest);
    } else {
        std::error_code ignored;  // a folder that cannot be made is each item's "cannot write" line
        std::filesystem::create_directories(options.out_dir, ignored);
        const std::vector<std::string> scenes = expand_scene_inputs(options.inputs);
        for (std::size_t i = 0; i < scenes.size(); ++i)
            items.push_back({i, scenes[i], output_for(scenes[i], options.out_dir, ".png"),
                             options.raw ? output_for(scenes[i], options.out_dir, ".pfm") : "", ""});
    }
    const grading::Shard shard = grading::parse_shard(options.shard);
    std::vector<BatchItem> mine;
    for (std::size_t i = 0; i < items.size(); ++i)
        if (int(i % std::size_t(shard.n)) == shard.k - 1) mine.push_back(items[i]);
    return mine;
}

// Paths are bytes; the report's are shown as grade shows names
// (grading/submissions.h: shown_name): as they are when valid UTF-8 without
// controls, a Latin-1 byte as \xE9.
nlohmann::json report_entry(const BatchItem& item, const std::string& error, double seconds) {
    const auto shown = [](const std::string& path) { return grading::shown_name(path); };
    return {{"scene", shown(item.scene)}, {"status", error.empty() ? "ok" : "failed"}, {"message", error},
            {"seconds", seconds}, {"out", error.empty() ? shown(item.out) : ""}, {"raw", error.empty() ? shown(item.raw) : ""}};
}

}  // namespace

void add_batch_command(CLI::App& app) {
    auto options = std::make_shared<BatchCommandOptions>();
    CLI::App* command = app.add_subcommand("batch", "Render every scene of a manifest, or of folders or patterns, in one process");
    command->add_option("manifest", options->inputs,
                        "JSON array of {\"scene\": \"a.json\", \"out\": \"a.png\", \"raw\": \"a.pfm\"}; "
                        "paths relative to the manifest's folder. With --out: scene files, folders of *.json, "
                        "or quoted glob patterns")
        ->required()
        ->expected(1, -1);
    command->add_option("--out", options->out_dir, "Render scenes (not a manifest) into this folder as NAME.png");
    command->add_flag("--raw", options->raw, "With --out: also write NAME.pfm");
    command->add_option("--report", options->report,
                        "Write a JSON report: per scene its status, message, seconds and output paths");
    command->add_option("--shard", options->shard, "Render only shard K of N (every N-th scene from the K-th), e.g. 2/4")
        ->capture_default_str();
    command->add_option("--backend", options->backend, "GL context: auto (EGL, then OSMesa), egl or osmesa")
        ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
    command->add_option("--scene-timeout", options->scene_timeout,
                        "Skip a scene not drawn within SECONDS of starting to load it (0: no limit)")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    command->add_flag("--allow-brdf", options->allow_brdf,
                      "Accept materials from .brdf files (their shader code runs; off: a scene with one is an error)");
    command->callback([options]() {
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
        // Usage errors (exit 2), before anything is read or written.
        try {
            if (options->out_dir.empty() && options->inputs.size() != 1)
                throw std::invalid_argument("batch: give one MANIFEST.json, or scenes, folders or patterns with --out DIR");
            grading::parse_shard(options->shard);
        } catch (const std::invalid_argument& error) {
            std::cerr << error_line(error.what()) << "\n";
            throw CLI::RuntimeError(kExitUsage);
        }
        // Mesa's shader cache in --out, not the user's home (a .brdf is code);
        // a manifest names no one folder: with --allow-brdf, no cache at all.
        if (!options->out_dir.empty())
            keep_shader_cache_in((std::filesystem::absolute(options->out_dir) / kShaderCacheFolder).string());
        else if (options->allow_brdf)
            switch_shader_cache_off();
        std::size_t failures = 0;
        try {
            std::string manifest;
            std::vector<BatchItem> items = batch_items(*options, manifest);
            check_batch_files(items, manifest, options->report);
            total = items.size();
            // Made when the first scene is drawn: a batch of broken scenes never needs one.
            std::unique_ptr<Capture> capture;
            const Backend backend = parse_backend(options->backend);
            const auto make_capture = [&]() -> Capture& {
                if (!capture) capture = std::make_unique<Capture>(make_headless_context(backend));
                return *capture;
            };
            Progress progress(items.size(), interactive);
            BatchOptions batch;
            batch.on_written = [&] { ++written; };
            batch.scene_timeout_s = options->scene_timeout;
            // A render with NaN or infinite pixels: written, exit status unchanged, one line.
            std::map<const BatchItem*, std::string> warnings;
            // Lines on stderr are printed under the file-commit lock, which an
            // interrupt takes for good before its own line: that line stays
            // the last (a scene's progress line printed after it would say
            // the batch went on).
            batch.warned = [&](std::size_t, const BatchItem& item, const std::string& warning) {
                const std::lock_guard<std::mutex> hold(temporary_files::lock());
                std::cerr << (interactive ? "\r\033[K" : "") << warning << "\n";
                warnings[&item] = text::one_line(warning.substr(std::string("m3055: warning: ").size()));
            };
            // Seconds between one item's report and the next: rendering and
            // writing overlap, so this is each item's share of the run's time.
            nlohmann::json report = nlohmann::json::array();
            auto last = std::chrono::steady_clock::now();
            // A .brdf file is code: a class's scenes run it only when asked to.
            failures = run_batch(
                make_capture, items, LoadContext::for_class(options->allow_brdf),
                [&](std::size_t, const BatchItem& item, const std::string& error) {
                    const auto now = std::chrono::steady_clock::now();
                    report.push_back(report_entry(item, error, std::chrono::duration<double>(now - last).count()));
                    report.back()["warning"] = warnings.count(&item) ? warnings[&item] : "";
                    last = now;
                    const std::lock_guard<std::mutex> hold(temporary_files::lock());
                    progress.step(item.out, error);
                },
                batch);
            progress.finish();
            if (!options->report.empty()) {
                const std::string text = report.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
                write_file_atomic(options->report, text.data(), text.size());
            }
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
