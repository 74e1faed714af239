// `m3055 bench [--out DIR] [--quick]`: run time against error.
#include "bench/bench.h"
#include "bench/area_bench.h"
#include "bench/area_latency.h"
#include "bench/brdf_bench.h"
#include "bench/model_bench.h"
#include "commands.h"

#include <iostream>

namespace m3055 {

void add_bench_command(CLI::App& app) {
    struct Options {
        bench::BenchOptions bench;
        std::string backend = "auto";
        std::string brdf;  // --brdf DIR: only the .brdf section (app/bench/brdf_bench.h)
        bool area = false;  // --area-lights: only the area lights' section (app/bench/area_bench.h)
        bool area_latency = false;  // --area-latency: only the explorer's area-light drag (app/bench/area_latency.h)
        bool models = false;  // --model-files: only the model files' section (app/bench/model_bench.h)
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "bench", "Benchmark run time against error; writes bench.md, bench.csv, bench.gp and bench.png (gnuplot)");
    command->add_option("--out", options->bench.out, "Output folder (default: bench)");
    command->add_option("--scenes", options->bench.scenes,
                        "Folder with the paper's scenes (default: ./scenes, then scenes/ beside the build folder)");
    command->add_flag("--quick", options->bench.quick, "Few repetitions and a small batch: a smoke run, rough numbers");
    command->add_flag("--latency", options->bench.latency_only,
                      "Only the explorer latency section: writes latency.md");
    command->add_flag("--replot", options->bench.replot,
                      "Measure nothing: redraw bench.gp and bench.png from the bench.csv in --out")
        ->excludes("--quick");
    command->add_option("--backend", options->backend, "GL context: auto (EGL, then OSMesa), egl or osmesa")
        ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
    command->add_option("--brdf", options->brdf,
                        "Only the .brdf section: the files of DIR (tests/data/brdf) against their built-in "
                        "models, written to --out/brdf.md")
        ->excludes("--replot");
    command->add_flag("--area-lights", options->area,
                      "Only the area lights' section: their sampling's frame time against its error from the "
                      "CPU reference, written to --out/area_lights.md and .csv")
        ->excludes("--replot");
    command->add_flag("--area-latency", options->area_latency,
                      "Only the explorer's latency with area lights: the softbox scene's key dragged, written to "
                      "--out/area_latency.md")
        ->excludes("--replot");
    command->add_flag("--model-files", options->models,
                      "Only the model files' section: a million-triangle OBJ and .glb (made at bench time) loaded "
                      "and shown, each step timed, written to --out/model_files.md and .csv")
        ->excludes("--replot");
    command->callback([options]() {
        try {
            options->bench.backend = parse_backend(options->backend);
            if (!options->brdf.empty()) return bench::run_brdf_bench(options->bench, options->brdf);
            if (options->area) return bench::run_area_bench(options->bench);
            if (options->area_latency) return bench::run_area_latency(options->bench);
            if (options->models) return bench::run_model_bench(options->bench);
            bench::run_bench(options->bench);
        } catch (const std::exception& error) {
            std::cerr << "m3055: " << error.what() << "\n";
            throw CLI::RuntimeError(kExitFailure);
        }
    });
}

}  // namespace m3055
