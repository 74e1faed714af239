// `m3055 brdf-check FILE.brdf | MODEL [--set NAME=VALUE ...]`: checks any
// model's BRDF, evaluated on the GPU by the renderer's own code
// (passes/brdf_grid.h), and prints one table: NaN / Inf / negative values over
// a grid of (L, V) at the corners of the parameter ranges, Helmholtz
// reciprocity, the largest directional albedo, and the distribution's
// normalization where the model declares one. Exit 1 on any NaN, Inf or
// negative value (and, with --require-conserving, on an albedo above 1.01).
#include "commands.h"
#include "progress.h"

#include "analysis/brdf_check.h"
#include "analysis/brdf_target.h"
#include "gl/context.h"
#include "gl/program.h"
#include "models/model_spec.h"
#include "passes/brdf_grid.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace m3055 {

namespace {

constexpr int kThetaSteps = 12, kPhiSteps = 16;   // 193 directions: 37 249 (L, V) pairs a setting
// (theta every 7.5 deg to 90, phi every 22.5 deg: L = V, mirror and retro directions included)
constexpr int kMuCells = 64, kAlbedoPhiCells = 128;  // 8192 incident directions for the albedo
const std::vector<double> kViewDegrees = {0, 15, 30, 45, 60, 75, 85, 89};

std::string number(double x, const char* format = "%.3g") {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, x);
    return buffer;
}

struct Report {
    GridStats grid;
    std::vector<Material> corners;
    std::vector<dvec3> dirs;
    std::size_t settings = 0, directions = 0;
    std::vector<double> albedo;
    std::optional<DistributionIntegral> D;
};

Report measure(const BrdfTarget& target, BrdfGrid& grid) {
    Report r;
    r.dirs = check_directions(kThetaSteps, kPhiSteps);
    r.directions = r.dirs.size();
    r.corners = parameter_corners(target);
    r.settings = r.corners.size();
    for (std::size_t k = 0; k < r.corners.size(); ++k)
        merge(r.grid, grid_stats(grid.evaluate(r.corners[k], r.dirs, r.dirs), r.dirs), long(k));
    const AlbedoSamples samples = albedo_samples(kMuCells, kAlbedoPhiCells);
    r.albedo = directional_albedo(grid.evaluate(target.material, samples.L, view_directions(kViewDegrees)), samples,
                                  kViewDegrees.size());
    r.D = distribution_integral(target.material);
    return r;
}

std::string angles(const dvec3& d) {
    return "(" + number(std::acos(std::min(1.0, d.z)) * 180.0 / 3.14159265358979323846, "%.1f") + ", " +
           number(std::atan2(d.y, d.x) * 180.0 / 3.14159265358979323846, "%.1f") + ")";
}

// Where the first bad value is: the directions and the parameters that differ from the defaults.
std::string first_bad(const BrdfTarget& target, const Report& r) {
    if (r.grid.first_bad < 0) return "";
    const std::size_t n = r.dirs.size();
    std::string where = "; first at L " + angles(r.dirs[std::size_t(r.grid.first_bad) % n]) + ", V " +
                        angles(r.dirs[std::size_t(r.grid.first_bad) / n]) + " (theta, phi deg)";
    const Material& m = r.corners[std::size_t(r.grid.first_setting)];
    std::string changed;
    for (const ParamSpec& p : m.model().params)
        if (p.kind == ParamKind::number && m.number(p.name) != target.material.number(p.name))
            changed += " " + p.label + "=" + number(m.number(p.name), "%g");
        else if (p.kind == ParamKind::flag && m.flag(p.name) != target.material.flag(p.name))
            changed += " " + p.label + "=" + (m.flag(p.name) ? "1" : "0");
    return where + (changed.empty() ? ", defaults" : "," + changed);
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
        << " values; max f " << number(r.grid.max_value) << first_bad(target, r) << " |\n"
        << "| exactly grazing view (N.V = 0, a silhouette's limit; not counted above) | "
        << (r.grid.grazing_nonfinite ? "warning" : "finite") << " | " << r.grid.grazing_nonfinite << " NaN/Inf |\n"
        << "| reciprocity: max \\|f(L,V) - f(V,L)\\| / max(\\|f(L,V)\\|, \\|f(V,L)\\|) | "
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
