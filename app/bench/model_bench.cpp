#include "model_bench.h"

#include "model_bench_files.h"
#include "timing.h"
#include "uv_sphere.h"
#include "frame/renderer.h"
#include "geometry/mesh.h"
#include "io/input_file.h"
#include "model_file/gltf_file.h"
#include "model_file/model_limits.h"
#include "model_file/obj_file.h"
#include "model_file/vertex_normals.h"
#include "scene/presets.h"
#include "scene/shape_limits.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <unistd.h>

namespace m3055::bench {

namespace {

namespace fs = std::filesystem;

struct Steps {
    std::vector<double> read, parse, normals, place, first_frame, frame;
};

double median_of(const std::vector<double>& samples) { return summarize(samples).median_ms; }

Scene scene_with(std::shared_ptr<const model_file::Model> model) {
    Scene scene = default_scene();
    scene.display.width = 512, scene.display.height = 320;
    scene.lights = light_preset(LightPreset::three_point_white);
    Object mesh;
    mesh.shape = Shape::mesh;
    mesh.size = 2.0;
    mesh.model = std::move(model);
    mesh.file = "bench";
    mesh.groups.push_back({"", mesh.material, false});
    scene.objects = {mesh};
    return scene;
}

}  // namespace

void run_model_bench(const BenchOptions& options) {
    const int slices = 1000, stacks = 501;  // 2 * 1000 * 500 = 1 000 000 triangles
    const int reps = options.quick ? 1 : 5;
    const fs::path folder = fs::temp_directory_path() / ("m3055-model-bench-" + std::to_string(getpid()));
    fs::create_directories(folder);
    const UvSphere sphere = make_uv_sphere(slices, stacks);
    const std::string obj = (folder / "sphere.obj").string(), glb = (folder / "sphere.glb").string();
    write_bench_obj(sphere, obj);
    write_bench_glb(sphere, glb);
    const auto context = HeadlessContext::create(options.backend);
    const GlApi& gl = context->gl();
    Renderer renderer(gl);
    std::ostringstream md, csv;
    md << "A model file of " << sphere.triangles()
       << " triangles (a UV sphere without normals, made at bench time) loaded and shown at 512 x 320, three-point "
          "lights; medians of "
       << reps << " loads (one more first, not counted). The first frame places the mesh, builds and uploads its "
          "batch and draws; a frame after a camera move reuses the batch.\n\n"
       << "| file | MB | read ms | parse ms | normals ms | place ms | first frame ms | load + first frame s | "
          "frame ms | triangles/s |\n"
       << "|---|---|---|---|---|---|---|---|---|---|\n";
    csv << "file,bytes,triangles,read_ms,parse_ms,normals_ms,place_ms,first_frame_ms,frame_ms\n";
    for (const std::string& path : {obj, glb}) {
        const bool is_obj = path == obj;
        Steps steps;
        const model_file::SideFileReader no_side = [](const std::string&) -> std::string {
            throw model_file::ModelError("names no other file");
        };
        for (int rep = 0; rep <= reps; ++rep) {
            std::string bytes;
            const double read = time_ms([&]() { bytes = io::read_input_file(path, model_file::kMaxModelBytes); });
            model_file::Soup soup;
            const double parse = time_ms([&]() {
                soup = is_obj ? model_file::parse_obj(bytes, no_side, kMaxSceneTriangles)
                              : model_file::parse_gltf(bytes, true, no_side, kMaxSceneTriangles);
            });
            std::shared_ptr<model_file::Model> model;
            const double normals = time_ms([&]() {
                model = std::make_shared<model_file::Model>(model_file::finish_model(std::move(soup)));
            });
            Scene scene = scene_with(model);
            const double place = time_ms([&]() { (void)geometry::make_mesh(scene.objects[0]); });
            gl.Finish();
            const double first = time_ms([&]() {
                renderer.render(scene);
                gl.Finish();
            });
            scene.camera.position.x += 0.1;  // a drag on the display: the batch stays
            const double frame = time_ms([&]() {
                renderer.render(scene);
                gl.Finish();
            });
            if (rep == 0) continue;  // compiles the programs
            steps.read.push_back(read), steps.parse.push_back(parse), steps.normals.push_back(normals);
            steps.place.push_back(place), steps.first_frame.push_back(first), steps.frame.push_back(frame);
        }
        const double mb = double(fs::file_size(path)) / 1e6;
        const double total_s = (median_of(steps.read) + median_of(steps.parse) + median_of(steps.normals) +
                                median_of(steps.first_frame)) / 1000.0;
        const double per_second = sphere.triangles() / (median_of(steps.frame) / 1000.0);
        char row[400];
        std::snprintf(row, sizeof row, "| %s | %.1f | %.0f | %.0f | %.0f | %.0f | %.0f | %.2f | %.1f | %.3g |\n",
                      is_obj ? "OBJ" : "GLB", mb, median_of(steps.read), median_of(steps.parse),
                      median_of(steps.normals), median_of(steps.place), median_of(steps.first_frame), total_s,
                      median_of(steps.frame), per_second);
        md << row;
        std::cout << row << std::flush;
        std::snprintf(row, sizeof row, "%s,%ju,%d,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f\n", is_obj ? "obj" : "glb",
                      std::uintmax_t(fs::file_size(path)), sphere.triangles(), median_of(steps.read),
                      median_of(steps.parse), median_of(steps.normals), median_of(steps.place),
                      median_of(steps.first_frame), median_of(steps.frame));
        csv << row;
    }
    std::error_code ec;
    fs::remove_all(folder, ec);
    fs::create_directories(options.out);
    std::ofstream(options.out + "/model_files.md") << md.str();
    std::ofstream(options.out + "/model_files.csv") << csv.str();
    std::cout << "wrote " << options.out << "/model_files.md and model_files.csv\n";
}

}  // namespace m3055::bench
