#include "brdf_bench.h"

#include "timing.h"
#include "brdf_file/brdf_model.h"
#include "image/image.h"
#include "frame/renderer.h"
#include "scene/presets.h"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace m3055::bench {

namespace {

struct Pair {
    std::string label;
    Material builtin, from_file;
};

// The built-in models and their .brdf copies, on the same parameter values.
std::vector<Pair> pairs(const std::string& dir) {
    auto file = [&](const std::string& name) { return Material(*load_brdf_model(dir + "/" + name).spec); };
    Material lambert = Material::of("lambert");
    lambert.set_vec3("kd", {0.7, 0.3, 0.2});
    Material blinn = Material::of("blinn_phong");
    blinn.set_vec3("kd", {0.7, 0.3, 0.2});
    blinn.set_number("shininess", 32);
    Material ggx = Material::of("microfacet");
    ggx.set_vec3("kd", {0.2, 0.5, 0.3});
    ggx.set_choice("distribution", "ggx");
    ggx.set_choice("fresnel", "schlick");
    ggx.set_lobes({{1.0, 0.3}});
    return {{"Lambert", lambert, file("lambert.brdf")},
            {"Blinn-Phong n 32", blinn, file("blinn_phong.brdf")},
            {"GGX + Schlick m 0.3", ggx, file("ggx_schlick.brdf")}};
}

// Nine spheres filling the view, three-point lighting, one material.
Scene scene_of(const Material& material, int width, int height) {
    Scene scene;
    scene.display.width = width, scene.display.height = height, scene.display.bits = 8;
    scene.camera.projection = Projection::perspective;
    scene.camera.fov_y_deg = 30;
    scene.camera.position = {0, 0, 9};
    scene.camera.target = {0, 0, 0};
    scene.lights = light_preset(LightPreset::three_point_white);
    for (int i = 0; i < 9; ++i) {
        Object o;
        o.center = {1.6 * (i % 3 - 1) * 1.6, 1.6 * (i / 3 - 1), 0};
        o.radius = 0.75;
        o.material = material;
        scene.objects.push_back(o);
    }
    return scene;
}

std::string ms(const TimeStats& t) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.2f", t.median_ms);
    return buffer;
}

}  // namespace

void run_brdf_bench(const BenchOptions& options, const std::string& brdf_dir) {
    const auto context = HeadlessContext::create(options.backend);
    const GlApi& gl = context->gl();
    const auto timed = [&](const std::function<void()>& draw) {
        gl.Finish();
        return time_ms([&]() {
            draw();
            gl.Finish();
        });
    };
    const int reps = options.quick ? 3 : 15, large_reps = options.quick ? 1 : 7, first_reps = options.quick ? 1 : 5;
    std::ostringstream md;
    md << "| model | 512×320 built-in ms | .brdf ms | ratio | 1920×1080 built-in ms | .brdf ms | ratio | "
          "first frame built-in ms | .brdf ms |\n|---|---|---|---|---|---|---|---|---|\n";
    Renderer renderer(gl);
    for (const Pair& p : pairs(brdf_dir)) {
        TimeStats t[2][2], first[2];
        for (int k = 0; k < 2; ++k) {
            const Material& m = k ? p.from_file : p.builtin;
            // A fresh renderer has no programs: its first frame compiles (Mesa's disk cache may help).
            first[k] = measure(0, first_reps, [&]() {
                Renderer fresh(gl);
                return timed([&]() { fresh.render(scene_of(m, 512, 320)); });
            });
            const Scene small = scene_of(m, 512, 320), large = scene_of(m, 1920, 1080);
            t[k][0] = measure(3, reps, [&]() { return timed([&]() { renderer.render(small); }); });
            t[k][1] = measure(3, large_reps, [&]() { return timed([&]() { renderer.render(large); }); });
        }
        char r0[16], r1[16];
        std::snprintf(r0, sizeof r0, "%.2f×", t[1][0].median_ms / t[0][0].median_ms);
        std::snprintf(r1, sizeof r1, "%.2f×", t[1][1].median_ms / t[0][1].median_ms);
        md << "| " << p.label << " | " << ms(t[0][0]) << " | " << ms(t[1][0]) << " | " << r0 << " | " << ms(t[0][1])
           << " | " << ms(t[1][1]) << " | " << r1 << " | " << ms(first[0]) << " | " << ms(first[1]) << " |\n";
    }
    std::filesystem::create_directories(options.out);
    const std::string text = "Medians: " + std::to_string(reps) + " frames at 512×320, " + std::to_string(large_reps) +
                             " at 1920×1080 after 3 warm-up frames, " + std::to_string(first_reps) +
                             " first frames (fresh renderer); nine spheres, three-point lighting.\n\n" + md.str();
    write_file_atomic((std::filesystem::path(options.out) / "brdf.md").string(), text.data(), text.size());
    std::cout << text;
}

}  // namespace m3055::bench
