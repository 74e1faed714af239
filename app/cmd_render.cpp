// `m3055 render`: one scene to PNG (and PFM), headless (SPEC section 8).
#include "capture.h"
#include "commands.h"

#include "scene/load.h"

#include <iostream>

namespace m3055 {

void add_render_command(CLI::App& app) {
    struct Options {
        std::string scene, out, raw, backend = "auto";
        std::vector<std::string> sets;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("render", "Render a scene headless to PNG (and PFM)");
    command->add_option("--scene", options->scene, "Scene JSON file (SPEC section 7)")->required();
    command->add_option("--out", options->out, "Output PNG (8-bit RGB, quantized to display.bits)")->required();
    command->add_option("--raw", options->raw, "Also write the unquantized linear colour as PFM");
    command->add_option("--backend", options->backend, "GL context: auto (EGL, then OSMesa), egl or osmesa")
        ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
    command->add_option("--set", options->sets, "Override a scene value: path=value, e.g. objects[0].material.m=40");
    command->callback([options]() {
        try {
            std::vector<Override> overrides;
            for (const auto& text : options->sets) overrides.push_back(parse_override(text));
            const Scene scene = load_scene_file(options->scene, overrides);
            Capture capture(parse_backend(options->backend));
            capture.render_to_files(scene, options->out, options->raw);
        } catch (const std::exception& error) {
            std::cerr << "m3055: " << error.what() << "\n";
            throw CLI::RuntimeError(kExitFailure);
        }
    });
}

}  // namespace m3055
