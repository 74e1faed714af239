// `m3055 plot --view polar|slice|albedo|lobe --out FILE.png TARGET... [--set
// NAME=VALUE ...]`: BRDF Explorer's views of any model or .brdf file, headless,
// drawn by gnuplot (gnuplot-nox, installed by scripts/setup) from a script
// with the data inline; FILE.gp is written beside the PNG so it can be
// restyled. polar and albedo overlay every TARGET; slice and lobe show the first.
// `m3055 plot spectrum --out FILE.png [--scene S.json --light I --object I]
// [--kelvin K | --illuminant NAME] [--conductor NAME]`: the spectra of a
// (light, material) pair (docs/spec.md#74-the-spectra-in-use), as the explorer's Spectra plot.
#include "bench/plot.h"
#include "commands.h"
#include "plot_spectrum.h"
#include "plot_views.h"
#include "progress.h"

#include "gl/context.h"
#include "gl/program.h"
#include "image/image.h"
#include "scene/light_colour.h"
#include "scene/load.h"
#include "spectral/conductor.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

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
    const int status = bench::run_gnuplot(gnuplot, gp.string(), partial_path.string(), log.string());
    const std::string message = status == 0 ? "" : bench::first_line(log.string());
    std::error_code ignored;
    fs::remove(log, ignored);
    if (status != 0 || !fs::is_regular_file(partial_path)) {
        fs::remove(partial_path, ignored);
        throw std::runtime_error("plot: gnuplot failed on " + gp.string() + ": " + message);
    }
    fs::rename(partial_path, out);
}

std::string short_number(double x) {
    std::ostringstream text;
    text << x;
    return text.str();
}

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
    return out;
}

struct SpectrumOptions {
    std::string out, scene, illuminant, conductor;
    int light = 0, object = 0;
    double kelvin = 0.0;
};

// The (light, material) pair the options name; throws std::runtime_error with one line.
void plot_spectrum(const SpectrumOptions& o) {
    const auto fail = [](const std::string& text) { throw std::runtime_error("plot spectrum: " + text); };
    if (o.kelvin != 0.0 && !o.illuminant.empty()) fail("give --kelvin or --illuminant, not both");
    Scene scene;
    std::optional<Light> light;
    std::optional<Material> material;
    if (!o.scene.empty()) {
        scene = load_scene_file(o.scene, LoadContext::trusted());
        if (!scene.lights.empty()) {
            if (o.light < 0 || o.light >= int(scene.lights.size()))
                fail("--light " + std::to_string(o.light) + ": " + o.scene + " has lights 0 to " +
                     std::to_string(scene.lights.size() - 1));
            light = scene.lights[std::size_t(o.light)];
        } else if (o.light != 0) {
            fail("--light " + std::to_string(o.light) + ": " + o.scene + " has no lights");
        }
        if (!scene.objects.empty()) {
            if (o.object < 0 || o.object >= int(scene.objects.size()))
                fail("--object " + std::to_string(o.object) + ": " + o.scene + " has objects 0 to " +
                     std::to_string(scene.objects.size() - 1));
            material = scene.objects[std::size_t(o.object)].material;
        } else if (o.object != 0) {
            fail("--object " + std::to_string(o.object) + ": " + o.scene + " has no objects");
        }
    } else if (o.light != 0 || o.object != 0) {
        fail("--light and --object pick from a --scene; give one");
    }
    std::string error;
    if (o.kelvin != 0.0) {
        if (!(o.kelvin >= kMinLightKelvin && o.kelvin <= kMaxLightKelvin))
            fail("--kelvin: must be in [1000, 40000], got " + short_number(o.kelvin));
        Light made = light.value_or(Light{});
        if (!set_temperature(made, o.kelvin, &error)) fail(error);
        light = made;
    } else if (!o.illuminant.empty()) {
        const auto& names = light_illuminant_names();
        if (std::find(names.begin(), names.end(), o.illuminant) == names.end())
            fail("--illuminant " + o.illuminant + ": not a CIE illuminant (" + joined(names) + ")");
        Light made = light.value_or(Light{});
        if (!set_illuminant(made, o.illuminant, &error)) fail(error);
        light = made;
    }
    if (!o.conductor.empty()) {
        const auto& names = spectral::conductor_names();
        if (std::find(names.begin(), names.end(), o.conductor) == names.end())
            fail("--conductor " + o.conductor + ": not a measured metal (" + joined(names) + ")");
        Material metal = Material::of("metal");
        metal.set_choice("conductor", o.conductor);
        material = metal;
    }
    const SpectrumView view = spectrum_view(light ? &*light : nullptr, material ? &*material : nullptr);
    const std::string title = "light: " + view.light_label + "\nmaterial: " +
                              (view.reflectance_label.empty() ? view.no_reflectance : view.reflectance_label);
    draw(plot::spectrum_script(view, title), o.out);
}

void add_spectrum_command(CLI::App& plot) {
    auto options = std::make_shared<SpectrumOptions>();
    CLI::App* command = plot.add_subcommand(
        "spectrum", "The spectra of a light and a material (S(lambda) at luminance 1, R(lambda)), 380-780 nm");
    command->add_option("--out", options->out, "Output PNG (its gnuplot script beside it, .gp)")->required();
    command->add_option("--scene", options->scene, "Scene file: the light and the object below");
    command->add_option("--light", options->light, "The scene's light (index; default 0)");
    command->add_option("--object", options->object, "The scene's object whose material is plotted (index; default 0)");
    command->add_option("--kelvin", options->kelvin, "A black body at K kelvin as the light (1000-40000)");
    command->add_option("--illuminant", options->illuminant, "A CIE illuminant as the light (A, D65, F2, ...)");
    command->add_option("--conductor", options->conductor, "A measured metal as the material (gold, silver, ...)");
    command->callback([options]() {
        try {
            plot_spectrum(*options);
        } catch (const std::exception& error) {
            std::cerr << error_text(error) << "\n";
            throw CLI::RuntimeError(kExitFailure);
        }
    });
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
    command->add_option("targets", options->targets, "models or .brdf files (polar and albedo overlay them)");
    command->add_option("--view", options->view, "polar, slice (theta_h/theta_d), albedo or lobe (3D)")
        ->check(CLI::IsMember({"polar", "slice", "albedo", "lobe"}));
    command->add_option("--out", options->out, "Output PNG (its gnuplot script beside it, .gp)");
    command->add_option("--set", options->sets, "NAME=VALUE for every target, repeatable");
    command->add_option("--theta-in", options->view_options.theta_in_deg, "Incident angle, degrees (polar, lobe)")
        ->check(CLI::Range(0.0, 89.9));
    command->add_flag("--log", options->view_options.log, "Log scale (polar radius, slice colour)");
    command->add_option("--backend", options->backend, "GL context: auto (EGL, then OSMesa), egl or osmesa")
        ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
    add_spectrum_command(*command);
    command->callback([options, command]() {
        if (command->got_subcommand("spectrum")) return;  // it has drawn its plot
        // Required unless `plot spectrum` is given: CLI11's usage errors, as before.
        if (options->targets.empty()) throw CLI::RequiredError("targets (or the subcommand spectrum)");
        if (options->out.empty()) throw CLI::RequiredError("--out");
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
