#include "explore/files.h"

#include "explore/figure_scenes.h"
#include "explore/operations.h"
#include "explore/undo.h"
#include "image/image.h"
#include "scene/load.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <system_error>

namespace m3055::explore {

void set_scene(ExplorerState& state, const Scene& scene, const std::string& name) {
    note_edit(state, "load " + name);
    state.scene = scene;
    state.camera_home = scene.camera;
    state.scene_name = name;
    state.selected_object = 0;
    state.selected_light = 0;
    if (!scene.objects.empty()) state.material_b = scene.objects[0].material;
    state.b_edited = false;
}

bool load_scene(ExplorerState& state, const std::string& path) {
    try {
        set_scene(state, load_scene_file(path, LoadContext::trusted()), path);
        state.scene_file = path;
        mark_saved(state);
        state.save_dir = std::filesystem::path(path).parent_path().string();
        state.status = "loaded " + path;
        state.error.clear();
        state.load_error.clear();
        return true;
    } catch (const std::exception& e) {  // SceneError names file and JSON path
        state.error = state.load_error = e.what();
        return false;
    }
}

bool load_figure(ExplorerState& state, const std::string& name) {
    for (const FigureScene& figure : figure_scenes()) {
        if (figure.name != name) continue;
        try {
            const std::string source = "scenes/" + name + ".json";
            set_scene(state, scene_from_json(nlohmann::json::parse(figure.json), source, LoadContext::trusted()),
                      source);
            // Built in: unsaved once edited; Ctrl+S asks where to save
            // (proposing NAME.json, never the file of the scene it replaced).
            state.scene_file.clear();
            mark_saved(state);
            note_edit(state, "figure preset " + name);
            state.status = "figure preset " + name;
            state.error.clear();
            return true;
        } catch (const std::exception& e) {
            state.error = e.what();
            return false;
        }
    }
    state.error = "no figure preset named '" + name + "'";
    return false;
}

namespace {

// The text of a saved scene file (Save, a screenshot's JSON): .brdf files
// named as the platform asks (ExplorerState::Platform::brdf_paths_relative_to).
std::string scene_file_text(const ExplorerState& state) {
    return scene_to_json(state.scene, PathWriting{state.platform.brdf_paths_relative_to}).dump(2) + "\n";
}

}  // namespace

bool save_scene(ExplorerState& state, const std::string& path) {
    try {
        const std::string text = scene_file_text(state);
        write_file_atomic(path, text.data(), text.size());
        if (state.platform.file_written) state.platform.file_written(path);
        state.scene_file = path;
        state.overwrite_warned.clear();
        state.save_dir = std::filesystem::path(path).parent_path().string();
        state.scene_name = std::filesystem::path(path).filename().string();
        commit_edits(state);  // the edits before the save are a step; the save itself is none
        state.history.set_head_file(state.scene_name, path);
        mark_saved(state);
        std::error_code ec;
        const auto full = std::filesystem::absolute(path, ec);
        state.status = "saved " + (ec ? path : full.string());
        return true;
    } catch (const std::exception& e) {
        state.error = e.what();
        return false;
    }
}

void save_or_ask(ExplorerState& state) {
    if (state.scene_file.empty()) request_save_as(state);
    else save_scene(state, state.scene_file);
}

std::string save_as_proposal(const ExplorerState& state) {
    if (!state.scene_file.empty()) return state.scene_file;
    std::string name = state.save_name;
    const std::filesystem::path from(state.scene_name);
    if (from.extension() == ".json") name = from.filename().string();  // a figure preset: fig10.json
    return state.save_dir.empty() ? name : (std::filesystem::path(state.save_dir) / name).string();
}

void request_save_as(ExplorerState& state) {
    state.save_path = save_as_proposal(state);
    state.overwrite_warned.clear();
    state.save_as_requested = true;
}

bool save_as(ExplorerState& state, const std::string& path) {
    std::error_code ec;
    const bool own = !state.scene_file.empty() && std::filesystem::equivalent(path, state.scene_file, ec);
    if (!own && std::filesystem::exists(path, ec) && state.overwrite_warned != path) {
        state.overwrite_warned = path;
        state.error = path + " exists and is not this scene's file: Save again to overwrite it";
        return false;
    }
    return save_scene(state, path);
}

std::string next_screenshot_path(const ExplorerState& state) {
    namespace fs = std::filesystem;
    const std::string stem = state.scene_file.empty() ? "m3055" : fs::path(state.scene_file).stem().string();
    const fs::path dir = state.screenshot_dir.empty() ? fs::path(".") : fs::path(state.screenshot_dir);
    for (int n = 1;; ++n) {
        char number[16];
        std::snprintf(number, sizeof number, "-%04d", n);
        const fs::path png = dir / (stem + number + ".png"), json = dir / (stem + number + ".json");
        std::error_code ec;
        if (!fs::exists(png, ec) && !fs::exists(json, ec)) return png.string();
    }
}

namespace {

// PATH.png -> PATH.json (a path without an extension gets one).
std::string json_beside(const std::string& png_path) {
    const auto dot = png_path.find_last_of('.');
    const auto slash = png_path.find_last_of('/');
    const bool has_extension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
    return (has_extension ? png_path.substr(0, dot) : png_path) + ".json";
}

}  // namespace

// The screenshot: exactly what `m3055 render` writes for the saved scene (the
// same Renderer, the same read_display and write_png), and the scene beside it.
// A script's `screenshot PATH` names the file; F12 takes the next free
// NAME-0001.png in the chosen folder, so nothing is overwritten.
void take_screenshot(ExplorerState& state, Renderer& renderer) {
    const std::string png = state.screenshot_path.empty() ? next_screenshot_path(state) : state.screenshot_path;
    state.screenshot_path.clear();
    try {
        // The screenshot waits for the specialized program (as `m3055 render` uses).
        const bool deferring = renderer.defers_compiles();
        renderer.set_defer_compiles(false);
        renderer.render(state.scene);
        renderer.set_defer_compiles(deferring);
        write_png(png, renderer.read_display());
        const std::string json = json_beside(png), text = scene_file_text(state);
        write_file_atomic(json, text.data(), text.size());
        if (state.platform.file_written) {
            state.platform.file_written(png);
            state.platform.file_written(json);
        }
        std::error_code ec;
        const std::string full = std::filesystem::absolute(png, ec).string();
        state.status = "screenshot " + (ec ? png : full) + " + " + json_beside(ec ? png : full);
    } catch (const std::exception& e) {
        state.error = e.what();
    }
}

}  // namespace m3055::explore
