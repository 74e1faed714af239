// `m3055 plot --view polar|slice|albedo|lobe --out FILE.png TARGET... [--set
// NAME=VALUE ...]`: BRDF Explorer's views of any model or .brdf file, headless,
// drawn by gnuplot (gnuplot-nox, installed by scripts/setup) from a script
// with the data inline; FILE.gp is written beside the PNG so it can be
// restyled. polar and albedo overlay every TARGET; slice and lobe show the first.
#include "bench/plot.h"
#include "commands.h"
#include "plot_views.h"
#include "progress.h"

#include "gl/context.h"
#include "gl/program.h"
#include "image/image.h"

#include <unistd.h>

#include <filesystem>
#include <iostream>

namespace m3055 {

namespace {

namespace fs = std::filesystem;

// Writes the script beside `png`, runs gnuplot into a temporary, renames it.
void draw(const std::string& script, const std::string& png) {
    const fs::path out = fs::absolute(png);
    const fs::path gp = fs::path(out).replace_extension(".gp");
    write_file_atomic(gp.string(), script.data(), script.size());
    const std::string gnuplot = bench::find_gnuplot();
    if (gnuplot.empty()) throw std::runtime_error("plot: no gnuplot on $PATH (Debian: gnuplot-nox); wrote " + gp.string());
    const std::string partial = "." + out.filename().string() + "." + std::to_string(getpid()) + ".partial";
    const fs::path dir = out.parent_path(), partial_path = dir / partial, log = dir / (partial + ".log");
    const int status = bench::run_gnuplot(gnuplot, dir.string(), gp.string(), partial, log.string());
    const std::string message = status == 0 ? "" : bench::first_line(log.string());
    std::error_code ignored;
    fs::remove(log, ignored);
    if (status != 0 || !fs::is_regular_file(partial_path)) {
        fs::remove(partial_path, ignored);
        throw std::runtime_error("plot: gnuplot failed on " + gp.string() + ": " + message);
    }
    fs::rename(partial_path, out);
}

}  // namespace

void add_plot_command(CLI::App& app) {
    struct Options {
        std::string view = "polar", out, backend = "auto";
        std::vector<std::string> targets, sets;
        plot::ViewOptions view_options;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("plot", "BRDF Explorer's views of a model or .brdf file as a PNG");
    command->add_option("targets", options->targets, "models or .brdf files (polar and albedo overlay them)")->required();
    command->add_option("--view", options->view, "polar, slice (theta_h/theta_d), albedo or lobe (3D)")
        ->check(CLI::IsMember({"polar", "slice", "albedo", "lobe"}));
    command->add_option("--out", options->out, "Output PNG (its gnuplot script beside it, .gp)")->required();
    command->add_option("--set", options->sets, "NAME=VALUE for every target, repeatable");
    command->add_option("--theta-in", options->view_options.theta_in_deg, "Incident angle, degrees (polar, lobe)")
        ->check(CLI::Range(0.0, 89.9));
    command->add_flag("--log", options->view_options.log, "Log scale (polar radius, slice colour)");
    command->add_option("--backend", options->backend, "GL context: auto (EGL, then OSMesa), egl or osmesa")
        ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
    command->callback([options]() {
        try {
            std::vector<BrdfTarget> targets;
            for (const std::string& t : options->targets) targets.push_back(brdf_target(t, options->sets));
            const auto context = HeadlessContext::create(parse_backend(options->backend));
            BrdfGrid grid(context->gl());
            const plot::ViewOptions& o = options->view_options;
            const std::string& v = options->view;
            const std::string script = v == "polar"    ? plot::polar_script(grid, targets, o)
                                       : v == "albedo" ? plot::albedo_script(grid, targets, o)
                                       : v == "slice"  ? plot::slice_script(grid, targets.front(), o)
                                                       : plot::lobe_script(grid, targets.front(), o);
            draw(script, options->out);
        } catch (const std::exception& error) {
            std::cerr << error_text(error) << "\n";
            throw CLI::RuntimeError(kExitFailure);
        }
    });
}

}  // namespace m3055
