// `m3055 figures`: renders the paper's figure scenes (scenes/fig*.json) to PNGs.
#include "commands.h"
#include "headless_context.h"

#include "capture/capture.h"
#include "scene/load.h"

#include <filesystem>
#include <iostream>

namespace m3055 {

void add_figures_command(CLI::App& app) {
    struct Options {
        std::string scenes = "scenes", out = "screenshots", backend = "auto";
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("figures", "Render the paper's figures (scenes/fig*.json) to PNG");
    command->add_option("--scenes", options->scenes, "Folder with fig*.json")->check(CLI::ExistingDirectory);
    command->add_option("--out", options->out, "Output folder");
    command->add_option("--backend", options->backend, "GL context: auto, egl or osmesa")
        ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
    command->callback([options]() {
        namespace fs = std::filesystem;
        std::vector<fs::path> files;
        for (const auto& entry : fs::directory_iterator(options->scenes)) {
            const std::string name = entry.path().filename().string();
            if (name.rfind("fig", 0) == 0 && entry.path().extension() == ".json") files.push_back(entry.path());
        }
        std::sort(files.begin(), files.end());
        if (files.empty()) {
            std::cerr << "m3055: " << options->scenes << ": no fig*.json scenes\n";
            throw CLI::RuntimeError(kExitFailure);
        }
        int failures = 0;
        try {
            fs::create_directories(options->out);
            Capture capture(make_headless_context(parse_backend(options->backend)));
            for (const auto& file : files) {
                const std::string out = (fs::path(options->out) / file.stem()).string() + ".png";
                try {
                    capture.render_to_files(load_scene_file(file.string(), LoadContext::trusted()), out, "");
                    std::cout << out << "\n";
                } catch (const std::exception& error) {
                    std::cerr << "m3055: " << error.what() << "\n";
                    ++failures;
                }
            }
        } catch (const std::exception& error) {
            std::cerr << "m3055: " << error.what() << "\n";
            throw CLI::RuntimeError(kExitFailure);
        }
        if (failures) throw CLI::RuntimeError(kExitFailure);
    });
}

}  // namespace m3055
