// `m3055 brdf-check FILE.brdf | MODEL [--set NAME=VALUE ...]`: checks any
// model's BRDF, evaluated on the GPU by the renderer's own code
// (passes/brdf_grid.h), and prints one table: NaN / Inf / negative values over
// a grid of (L, V) at the corners of the parameter ranges, Helmholtz
// reciprocity, the largest directional albedo, and the distribution's
// normalization where the model declares one. Exit 1 on any NaN, Inf or
// negative value (and, with --require-conserving, on an albedo above 1.01).
#include "capture.h"
#include "commands.h"
#include "progress.h"

#include "analysis/brdf_check.h"
#include "analysis/brdf_target.h"
#include "gl/context.h"
#include "models/model_spec.h"
#include "passes/brdf_grid.h"

#include <cstdio>
#include <iostream>
#include <sstream>

namespace m3055 {

namespace {

constexpr int kThetaSteps = 12, kPhiSteps = 16;   // 193 directions: 37 249 (L, V) pairs a setting
constexpr int kMuCells = 64, kAlbedoPhiCells = 128;  // 8192 incident directions for the albedo
const std::vector<double> kViewDegrees = {0, 15, 30, 45, 60, 75, 85, 89};

std::string number(double x, const char* format = "%.3g") {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, x);
    return buffer;
}

struct Report {
    GridStats grid;
    std::size_t settings = 0, directions = 0;
    std::vector<double> albedo;
    std::optional<DistributionIntegral> D;
};

Report measure(const BrdfTarget& target, BrdfGrid& grid) {
    Report r;
    const std::vector<dvec3> dirs = check_directions(kThetaSteps, kPhiSteps);
    r.directions = dirs.size();
    const std::vector<Material> corners = parameter_corners(target);
    r.settings = corners.size();
    for (const Material& m : corners) merge(r.grid, grid_stats(grid.evaluate(m, dirs, dirs), dirs));
    const AlbedoSamples samples = albedo_samples(kMuCells, kAlbedoPhiCells);
    r.albedo = directional_albedo(grid.evaluate(target.material, samples.L, view_directions(kViewDegrees)), samples,
                                  kViewDegrees.size());
    r.D = distribution_integral(target.material);
    return r;
}

bool print(const BrdfTarget& target, const Report& r, bool require_conserving) {
    const bool values_ok = r.grid.nonfinite == 0 && r.grid.negative == 0;
    std::size_t worst = 0;
    for (std::size_t i = 0; i < r.albedo.size(); ++i)
        if (r.albedo[i] > r.albedo[worst]) worst = i;
    const double albedo = r.albedo[worst];
    const bool conserving = albedo <= 1.01;
    std::ostringstream out;
    out << "m3055 brdf-check: " << target.name << " (" << target.material.model().label << ")\n\n"
        << "| check | result | value |\n|---|---|---|\n"
        << "| f finite and >= 0 on " << r.directions << " x " << r.directions << " (L, V) x " << r.settings
        << " parameter settings (defaults, range corners) | " << (values_ok ? "PASS" : "FAIL") << " | "
        << r.grid.nonfinite << " NaN/Inf, " << r.grid.negative << " negative of " << r.grid.values
        << " values; max f " << number(r.grid.max_value) << " |\n"
        << "| reciprocity: max \\|f(L,V) - f(V,L)\\| / max(f) | "
        << (r.grid.max_reciprocity <= 1e-3 ? "reciprocal" : "NOT reciprocal") << " | "
        << number(r.grid.max_reciprocity) << " |\n"
        << "| max directional albedo (defaults; " << kMuCells * kAlbedoPhiCells << " incident samples, views 0-89 deg) | "
        << (conserving ? "<= 1 (conserving)" : "GAIN x" + number(albedo)) << " | " << number(albedo, "%.4f")
        << " at " << number(kViewDegrees[worst], "%g") << " deg |\n";
    if (r.D)
        out << "| normalized distribution: integral D (N.h) dw (CPU reference D) | "
            << (std::abs(r.D->integral - r.D->weights) <= 1e-3 * std::max(1.0, r.D->weights) ? "normalized" : "NOT normalized")
            << " | " << number(r.D->integral, "%.6f") << " (sum of lobe weights " << number(r.D->weights, "%g") << ") |\n";
    std::cout << out.str();
    return values_ok && (!require_conserving || conserving);
}

}  // namespace

void add_brdf_check_command(CLI::App& app) {
    struct Options {
        std::string target, backend = "auto";
        std::vector<std::string> sets;
        bool require_conserving = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("brdf-check", "Check a model's or a .brdf file's BRDF: values, "
                                                         "reciprocity, albedo, normalization");
    command->add_option("target", options->target, "a .brdf file, or a model name (m3055 render's)")->required();
    command->add_option("--set", options->sets, "NAME=VALUE: a parameter held at VALUE (JSON), repeatable");
    command->add_flag("--require-conserving", options->require_conserving,
                      "Also fail when the directional albedo exceeds 1.01 (energy gain)");
    command->add_option("--backend", options->backend, "GL context: auto (EGL, then OSMesa), egl or osmesa")
        ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
    command->callback([options]() {
        bool ok = false;
        try {
            const BrdfTarget target = brdf_target(options->target, options->sets);
            const auto context = HeadlessContext::create(parse_backend(options->backend));
            BrdfGrid grid(context->gl());
            ok = print(target, measure(target, grid), options->require_conserving);
        } catch (const std::exception& error) {
            std::cerr << error_text(error) << "\n";
            throw CLI::RuntimeError(kExitFailure);
        }
        if (!ok) throw CLI::RuntimeError(kExitFailure);
    });
}

}  // namespace m3055
