#include "bench.h"
#include "core_cost.h"
#include "latency.h"
#include "models/model_table.h"

#include "mesh_renderer.h"
#include "plot.h"
#include "process_timing.h"
#include "results.h"

#include "gl/context.h"
#include "image/image.h"
#include "reference/reference.h"
#include "frame/renderer.h"
#include "scene/load.h"

#include <glm/common.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>

namespace m3055::bench {
namespace {

namespace fs = std::filesystem;

struct NamedScene {
    std::string name;
    Scene scene;
};

struct Plan {
    int warm_up, repetitions, large_warm_up, large_repetitions, reference_repetitions, large_reference_repetitions;
    int first_frame_repetitions, process_repetitions, batch_scenes;
    bool large;
};

Plan make_plan(bool quick) {
    if (quick) return {1, 2, 0, 0, 1, 0, 1, 2, 6, false};
    return {3, 15, 1, 7, 3, 1, 3, 10, 200, true};
}

Scene resized(Scene scene, int width, int height) {
    scene.display.width = width;
    scene.display.height = height;
    return scene;
}

// Fig. 10's Beckmann lobes (w, m) as the cheap exponent lobes with the same
// peak and the same width near the peak: exp(-tan^2 a / m^2) ~ cos^n a with
// n = 2 / m^2 for N.H (eq. 15); R.V turns twice as fast (the paper's remark),
// so n = 1 / (2 m^2) for eq. 16. Weights w / m^2 keep the peak delta(0) = 1/m^2.
Scene cheap_metal(Scene scene, const std::string& model) {
    for (Object& object : scene.objects) {
        if (object.material.model_name() != "metal") continue;
        std::vector<Lobe> lobes = object.material.lobes().to_vector();
        for (Lobe& lobe : lobes) {
            const double m2 = lobe.m * lobe.m;
            lobe = Lobe{lobe.w / m2, model == "metal_blinn" ? 2.0 / m2 : 1.0 / (2.0 * m2)};
        }
        object.material = with_model(object.material, model_table().get(model));
        object.material.set_lobes(lobes);
    }
    for (Light& light : scene.lights) light.lobes.clear();  // Fig. 10 has none; keep the comparison plain
    return scene;
}

WayResult make_way(const std::string& group, const std::string& way, const std::string& label,
                   const std::string& scenes, const std::string& against) {
    WayResult result;
    result.group = group, result.way = way, result.label = label, result.scenes = scenes;
    result.error_against = against;
    return result;
}

// The 1-, 5- and 15-minute load averages, or "" where /proc/loadavg is missing.
std::string load_average() {
    std::ifstream file("/proc/loadavg");
    std::string one, five, fifteen;
    if (!(file >> one >> five >> fifteen)) return "";
    return one + " " + five + " " + fifteen;
}

std::string scene_names(const std::vector<NamedScene>& scenes) {
    if (scenes.size() > 3) return std::to_string(scenes.size()) + " figure scenes (fig05-fig13)";
    std::string names;
    for (const auto& s : scenes) names += (names.empty() ? "" : " + ") + s.name;
    return names;
}

class Bench {
public:
    Bench(const BenchOptions& options, const Plan& plan) : options_(options), plan_(plan) {}

    BenchResults run() {
        const auto start = std::chrono::steady_clock::now();
        results_.load_before = load_average();
        results_.quick = options_.quick;
        results_.warm_up = plan_.warm_up;
        results_.repetitions = plan_.repetitions;
        results_.large_repetitions = plan_.large_repetitions;
        load_scenes();
        // Processes first: the in-process part below disables Mesa's shader
        // cache for itself (first-frame times must include the compile).
        measure_processes();
        setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
        context_ = HeadlessContext::create(options_.backend);
        results_.device = context_->renderer_string() + " via " + context_->backend_name();
        renderer_ = std::make_unique<Renderer>(context_->gl());
        mesh_ = std::make_unique<MeshRenderer>(context_->gl());
        compute_references();
        geometry_ways();
        cheap_metal_ways();
        shader_ways();
        specialization_table();
        results_.load_after = load_average();
        results_.total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return results_;
    }

private:
    std::string figure_count() const { return " (" + std::to_string(figures_.size()) + " figs)"; }

    void say(const std::string& text) { std::fprintf(stderr, "bench: %s\n", text.c_str()); }

    NamedScene load(const std::string& file) {
        return {file, load_scene_file((fs::path(scenes_dir_) / file).string(), LoadContext::trusted())};
    }

    void load_scenes() {
        scenes_dir_ = find_scenes_dir(options_.scenes);
        geometry_ = {load("spec_example.json"), load("fig10.json")};
        metal_ = {load("fig10.json")};
        for (const char* f : {"fig05.json", "fig06.json", "fig07.json", "fig08.json", "fig09.json", "fig10.json",
                              "fig11.json", "fig12.json", "fig13.json"})
            figures_.push_back(load(f));
        if (options_.quick) figures_.resize(3);  // highlight, translucent: enough for a smoke run
    }

    // ---- whole processes ----------------------------------------------------

    void measure_processes() {
        const std::string exe = self_executable();
        const std::string scene = (fs::path(scenes_dir_) / "spec_example.json").string();
        TempFolder tmp;
        const std::vector<std::string> render = {exe, "render", "--scene", scene, "--out", tmp.file("one.png")};
        say("whole process: one m3055 render, cold and warm shader cache");
        ProcessResult& p = results_.process;
        p.cold = measure(0, plan_.process_repetitions,
                         [&]() { return run_process_ms(render, {"MESA_SHADER_CACHE_DISABLE=true"}); });
        p.warm = measure(1, plan_.process_repetitions, [&]() { return run_process_ms(render); });

        // A grading run: different scenes (the figures with shifted colours), one manifest.
        say("batch throughput: " + std::to_string(plan_.batch_scenes) + " scenes, one batch against separate renders");
        nlohmann::json manifest = nlohmann::json::array();
        std::vector<std::string> scene_files;
        for (int i = 0; i < plan_.batch_scenes; ++i) {
            Scene s = figures_[i % figures_.size()].scene;
            for (Object& o : s.objects)
                if (o.material.has("color"))
                    o.material.set_vec3("color", glm::clamp(o.material.vec3("color") * (0.8 + 0.001 * i), 0.0, 1.0));
            const std::string name = "scene" + std::to_string(i);
            write_text(tmp.file(name + ".json"), scene_to_json(s, PathWriting::absolute()).dump(2));
            manifest.push_back({{"scene", name + ".json"}, {"out", name + "_batch.png"}});
            scene_files.push_back(tmp.file(name + ".json"));
        }
        write_text(tmp.file("manifest.json"), manifest.dump(1));
        p.batch_scenes = plan_.batch_scenes;
        p.batch_ms = run_process_ms({exe, "batch", tmp.file("manifest.json")});
        p.separate_ms = 0;
        for (int i = 0; i < plan_.batch_scenes; ++i)
            p.separate_ms += run_process_ms(
                {exe, "render", "--scene", scene_files[i], "--out", tmp.file("scene" + std::to_string(i) + ".png")});
        say("  batch " + std::to_string(int(p.batch_ms)) + " ms, separate " + std::to_string(int(p.separate_ms)) +
            " ms");
    }

    // ---- in-process frames --------------------------------------------------

    double finish_timed(const std::function<void()>& draw) {
        context_->gl().Finish();  // nothing from before is counted
        return time_ms([&]() {
            draw();
            context_->gl().Finish();
        });
    }

    // Mean frame time over a scene set, at 512 x 320 and (unless quick) 1920 x 1080.
    void time_way(WayResult& way, const std::vector<Scene>& scenes, const std::function<void(const Scene&)>& draw) {
        auto per_set = [&](const std::vector<Scene>& set) {
            return [&, set]() {
                double sum = 0;
                for (const Scene& s : set) sum += finish_timed([&]() { draw(s); });
                return sum / double(set.size());
            };
        };
        way.small = measure(plan_.warm_up, plan_.repetitions, per_set(scenes));
        if (plan_.large) {
            std::vector<Scene> large;
            for (const Scene& s : scenes) large.push_back(resized(s, 1920, 1080));
            way.large = measure(plan_.large_warm_up, plan_.large_repetitions, per_set(large));
        }
    }

    const ref::ReferenceImage& reference_of(const std::string& key) { return references_.at(key); }

    void compute_references() {
        say("double CPU reference (also timed)");
        // Every scene any way is compared with, rendered once and kept.
        for (const auto* set : {&figures_, &geometry_, &metal_})
            for (const auto& s : *set)
                if (!references_.count(s.name)) references_[s.name] = ref::render_reference(s.scene);
        WayResult way = make_way("CPU reference", "double-precision CPU reference (ref::render_reference)",
                                 "CPU double" + figure_count(),
                      scene_names(figures_), "itself");
        std::vector<Scene> figure_scenes;
        for (const auto& s : figures_) figure_scenes.push_back(s.scene);
        auto per_set = [&](const std::vector<Scene>& set) {
            return [set]() {
                double sum = 0;
                for (const Scene& s : set) sum += time_ms([&]() { ref::render_reference(s); });
                return sum / double(set.size());
            };
        };
        way.small = measure(0, plan_.reference_repetitions, per_set(figure_scenes));
        if (plan_.large && plan_.large_reference_repetitions > 0) {
            std::vector<Scene> large;
            for (const Scene& s : figure_scenes) large.push_back(resized(s, 1920, 1080));
            way.large = measure(0, plan_.large_reference_repetitions, per_set(large));
        }
        way.exact_reference = true;
        reference_way_ = way;
    }

    WayResult renderer_way(const std::string& group, const std::string& name, const std::string& label,
                           const std::vector<NamedScene>& scenes, ShaderMode mode,
                           const std::function<Scene(const Scene&)>& transform = nullptr,
                           const std::string& against = "double reference") {
        say(name);
        WayResult way = make_way(group, name, label, scene_names(scenes), against);
        std::vector<Scene> set;
        for (const auto& s : scenes) set.push_back(transform ? transform(s.scene) : s.scene);
        renderer_->set_shader_mode(mode);
        ErrorAccumulator error;
        for (std::size_t i = 0; i < set.size(); ++i) {
            renderer_->render(set[i]);
            error.add(renderer_->read_raw(), reference_of(scenes[i].name), set[i].display.bits);
        }
        way.error = error.result();
        time_way(way, set, [&](const Scene& s) { renderer_->render(s); });
        renderer_->set_shader_mode(ShaderMode::specialized);
        return way;
    }

    void geometry_ways() {
        results_.ways.push_back(renderer_way("exact ray-cast", "exact ray-cast spheres (the renderer)", "ray-cast",
                                             geometry_, ShaderMode::specialized));
        const int levels[][2] = {{8, 4}, {16, 8}, {32, 16}, {64, 32}, {128, 64}};
        for (const auto& level : levels) {
            mesh_->set_tessellation(level[0], level[1]);
            const std::string size = std::to_string(level[0]) + "x" + std::to_string(level[1]);
            const std::string triangles = std::to_string(mesh_->triangles_per_sphere()) + " triangles";
            for (Interpolation interpolation : {Interpolation::per_pixel, Interpolation::gouraud}) {
                const bool gouraud = interpolation == Interpolation::gouraud;
                WayResult way = make_way(gouraud ? "mesh Gouraud" : "mesh per-pixel",
                              "UV sphere " + size + " (" + triangles + "), " +
                                  (gouraud ? "shaded per vertex (Gouraud)" : "shaded per pixel"),
                              size, scene_names(geometry_), "double reference");
                say(way.way);
                ErrorAccumulator error;
                for (const auto& s : geometry_) {
                    mesh_->render(s.scene, interpolation);
                    error.add(mesh_->read_raw(), reference_of(s.name), s.scene.display.bits);
                }
                way.error = error.result();
                std::vector<Scene> set;
                for (const auto& s : geometry_) set.push_back(s.scene);
                time_way(way, set, [&](const Scene& s) { mesh_->render(s, interpolation); });
                results_.ways.push_back(way);
            }
        }
    }

    void cheap_metal_ways() {
        const std::string against = "double reference of eq. 12 (Fig. 10)";
        results_.ways.push_back(renderer_way("cheap metal", "eq. 12 metal (Cook-Torrance, Beckmann), Fig. 10",
                                             "eq.12 (Fig.10)", metal_, ShaderMode::specialized, nullptr, against));
        results_.ways.push_back(renderer_way(
            "cheap metal", "eq. 15 metal_blinn, (N.H)^n, n = 2/m^2, w/m^2", "eq.15 blinn", metal_,
            ShaderMode::specialized, [](const Scene& s) { return cheap_metal(s, "metal_blinn"); }, against));
        results_.ways.push_back(renderer_way(
            "cheap metal", "eq. 16 metal_phong, (R.V)^n, n = 1/(2m^2), w/m^2", "eq.16 phong", metal_,
            ShaderMode::specialized, [](const Scene& s) { return cheap_metal(s, "metal_phong"); }, against));
    }

    void shader_ways() {
        results_.ways.push_back(renderer_way("shaders", "specialized programs (default)",
                                             "specialized" + figure_count(), figures_,
                                             ShaderMode::specialized));
        results_.ways.push_back(
            renderer_way("shaders", "one general program", "general" + figure_count(), figures_, ShaderMode::general));
        results_.ways.push_back(reference_way_);
    }

    void specialization_table() {
        say("first frame and steady frame, specialized against general");
        for (const auto& s : figures_) {
            SpecializationResult row;
            row.scene = s.name;
            for (ShaderMode mode : {ShaderMode::specialized, ShaderMode::general}) {
                const bool specialized = mode == ShaderMode::specialized;
                // A fresh renderer has an empty program cache: its first frame compiles.
                const TimeStats first = measure(0, plan_.first_frame_repetitions, [&]() {
                    Renderer fresh(context_->gl());
                    fresh.set_shader_mode(mode);
                    return finish_timed([&]() { fresh.render(s.scene); });
                });
                renderer_->set_shader_mode(mode);
                const TimeStats steady = measure(plan_.warm_up, plan_.repetitions,
                                                 [&]() { return finish_timed([&]() { renderer_->render(s.scene); }); });
                (specialized ? row.first_specialized : row.first_general) = first;
                (specialized ? row.steady_specialized : row.steady_general) = steady;
            }
            renderer_->set_shader_mode(ShaderMode::specialized);
            results_.specialization.push_back(row);
        }
    }

    // A temporary folder for the process measurements, removed afterwards.
    struct TempFolder {
        std::string path;
        TempFolder() {
            std::string pattern = (fs::temp_directory_path() / "m3055-bench-XXXXXX").string();
            if (!mkdtemp(pattern.data())) throw std::runtime_error("bench: cannot make a temporary folder");
            path = pattern;
        }
        ~TempFolder() {
            std::error_code ignored;
            fs::remove_all(path, ignored);
        }
        std::string file(const std::string& name) const { return (fs::path(path) / name).string(); }
    };

    static void write_text(const std::string& path, const std::string& text) {
        write_file_atomic(path, text.data(), text.size());
    }

    const BenchOptions& options_;
    Plan plan_;
    std::string scenes_dir_;
    std::vector<NamedScene> geometry_, metal_, figures_;
    std::map<std::string, ref::ReferenceImage> references_;
    std::unique_ptr<HeadlessContext> context_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<MeshRenderer> mesh_;
    WayResult reference_way_;
    BenchResults results_;
};

}  // namespace

std::string find_scenes_dir(const std::string& requested) {
    if (!requested.empty()) return requested;
    std::vector<fs::path> candidates = {"scenes"};
    try {
        candidates.push_back(fs::path(self_executable()).parent_path().parent_path() / "scenes");
    } catch (const std::exception&) {
    }
    for (const auto& c : candidates)
        if (fs::exists(c / "fig10.json")) return c.string();
    throw std::runtime_error("bench: cannot find the scenes/ folder (fig10.json); give --scenes DIR");
}

namespace {

const char* const kPlotTitle = "Run time against error, per way of rendering (512 x 320)";

// bench.gp and bench.png; without gnuplot, one line on how to get the picture.
void plot(const std::string& out, const std::vector<PlotPoint>& points) {
    if (write_plot(out, points, kPlotTitle) == PlotOutcome::no_gnuplot)
        std::cerr << "m3055: bench: no bench.png, gnuplot is not installed: apt-get install gnuplot-nox "
                     "(or scripts/setup), then run `gnuplot bench.gp` in " << out << "\n";
}

}  // namespace

void run_figures_bench(const BenchOptions& options) {
    Bench bench(options, make_plan(options.quick));
    const BenchResults results = bench.run();
    fs::create_directories(options.out);
    const std::string md = markdown_report(results), csv = csv_report(results);
    write_file_atomic((fs::path(options.out) / "bench.md").string(), md.data(), md.size());
    write_file_atomic((fs::path(options.out) / "bench.csv").string(), csv.data(), csv.size());
    std::cout << md;
    plot(options.out, plot_points(results));
}

void run_bench(const BenchOptions& options) {
    if (options.replot) {
        plot(options.out, read_plot_points((fs::path(options.out) / "bench.csv").string()));
        return;
    }
    if (!options.latency_only) run_figures_bench(options);
    // The explorer latency section and the explorer core's costs: their own context, after the rest.
    const std::string latency = explorer_latency(options.backend).markdown() + "\n" + explorer_core_cost().markdown();
    fs::create_directories(options.out);
    write_file_atomic((fs::path(options.out) / "latency.md").string(), latency.data(), latency.size());
    std::cout << "\n" << latency;
}

}  // namespace m3055::bench
