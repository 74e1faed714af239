#include "area_bench.h"

#include "timing.h"
#include "frame/renderer.h"
#include "image/quantize.h"
#include "reference/reference.h"
#include "scene/load.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace m3055::bench {

namespace {

struct Setting {
    const char* label;
    AreaSampling sampling;
};

// The explorer's preview, the render's, and around them: the samples of each
// emitter (and as many of a highlight), a rect's or disk's probe (a ray a
// sample in a penumbra, the sky's always), and whether a highlight of whole
// exponent under a rect or the sky is integrated exactly.
const Setting kSettings[] = {
    {"fast preview (explorer)", kFastSampling},
    {"one point an emitter, no closed form", {1, 1}},
    {"2 x 2 samples, 2 x 2 probe", {2, 2}},
    {"4 x 4 samples, 3 x 3 probe", {4, 3}},
    {"8 x 8 samples, 3 x 3 probe", {8, 3}},
    {"8 x 8 samples, 3 x 3 probe, lobe closed form (render)", kRenderSampling},
    {"12 x 12 samples, 3 x 3 probe", {12, 3}},
    {"16 x 16 samples, 3 x 3 probe", {16, 3}},
};

struct Errors {
    double max_abs = 0, mean_abs = 0, mean_signed = 0, same_level = 0;
    int max_level = 0;
};

// On the reference's interior pixels, as tests/support/gpu_compare.cpp measures.
Errors errors_of(const RgbFloatImage& raw, const ref::ReferenceImage& reference, const Display& display) {
    const int w = display.width, h = display.height;
    Errors e;
    long pixels = 0, same = 0;
    double sum = 0, signed_sum = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!ref::is_interior(reference, x, y)) continue;
            ++pixels;
            bool same_level = true;
            for (int c = 0; c < 3; ++c) {
                const double expected = reference.rgb[(std::size_t(y) * w + x) * 3 + c];
                const double actual = raw.pixels[(std::size_t(h - 1 - y) * w + x) * 3 + c];
                e.max_abs = std::max(e.max_abs, std::abs(actual - expected));
                sum += std::abs(actual - expected);
                signed_sum += actual - expected;
                const int levels =
                    std::abs(quantize_level(actual, display.bits) - quantize_level(expected, display.bits));
                e.max_level = std::max(e.max_level, levels);
                if (levels) same_level = false;
            }
            if (same_level) ++same;
        }
    if (pixels) {
        e.mean_abs = sum / (3.0 * pixels);
        e.mean_signed = signed_sum / (3.0 * pixels);
        e.same_level = double(same) / pixels;
    }
    return e;
}

}  // namespace

void run_area_bench(const BenchOptions& options) {
    const std::string scenes = find_scenes_dir(options.scenes);
    const int width = options.quick ? 128 : 256, height = options.quick ? 80 : 160;
    const int reps = options.quick ? 1 : 5;
    const auto context = HeadlessContext::create(options.backend);
    const GlApi& gl = context->gl();
    Renderer renderer(gl);
    std::ostringstream md, csv;
    md << "Area lights at " << width << " x " << height
       << ": a frame's median time and its error against the CPU reference (interior pixels, 5-bit levels).\n\n"
       << "| scene | sampling | frame ms | max abs | mean abs | mean signed | same level | max levels |\n"
       << "|---|---|---|---|---|---|---|---|\n";
    csv << "scene,light_samples,probe,lobe_closed_form,frame_ms,max_abs,mean_abs,mean_signed,same_level,max_levels\n";
    for (const char* name : {"softbox_three_point.json", "sky_fill.json"}) {
        Scene scene = load_scene_file(scenes + "/" + name, LoadContext::trusted());
        scene.display.width = width, scene.display.height = height;
        std::cout << name << ": CPU reference ..." << std::flush;
        const auto start = std::chrono::steady_clock::now();
        const ref::ReferenceImage reference = ref::render_reference(scene);
        std::cout << " " << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
                  << " s\n";
        for (const Setting& setting : kSettings) {
            renderer.set_area_sampling(setting.sampling);
            const TimeStats t = measure(1, reps, [&]() {
                gl.Finish();
                return time_ms([&]() {
                    renderer.render(scene);
                    gl.Finish();
                });
            });
            const Errors e = errors_of(renderer.read_raw(), reference, scene.display);
            char row[320];
            std::snprintf(row, sizeof row, "| %s | %s | %.1f | %.4f | %.5f | %+.5f | %.2f %% | %d |\n", name,
                          setting.label, t.median_ms, e.max_abs, e.mean_abs, e.mean_signed, 100.0 * e.same_level,
                          e.max_level);
            md << row;
            std::cout << row << std::flush;
            std::snprintf(row, sizeof row, "%s,%d,%d,%d,%.3f,%.6f,%.7f,%.7f,%.5f,%d\n", name, setting.sampling.light,
                          setting.sampling.shadow, setting.sampling.lobe_closed_form ? 1 : 0, t.median_ms, e.max_abs,
                          e.mean_abs, e.mean_signed, e.same_level, e.max_level);
            csv << row;
        }
    }
    md << "\nOn llvmpipe the rows above 8 x 8 samples may be short of light near dense meshes: it leaves every\n"
          "loop of a fragment after 65 535 iterations in all, silently (docs/lights.md, \"fourth\").\n";
    std::filesystem::create_directories(options.out);
    std::ofstream(options.out + "/area_lights.md") << md.str();
    std::ofstream(options.out + "/area_lights.csv") << csv.str();
    std::cout << "wrote " << options.out << "/area_lights.md and area_lights.csv\n";
}

}  // namespace m3055::bench
