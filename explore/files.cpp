#include "explore/files.h"

#include "explore/edits.h"
#include "explore/figure_scenes.h"
#include "explore/operations.h"
#include "image/image.h"
#include "scene/load.h"
#include "scene/scene_text.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <optional>
#include <system_error>

namespace m3055::explore {

namespace {
// A preset's name in the title bar (a figure, or one of the scenes built in):
// what it is, not a path. It has no file, and "scenes/NAME.json" there read as
// the file Ctrl+S would write while the File section said there was none.
const std::string kPresetName = "preset ";
}  // namespace

std::string set_scene(Explorer& e, const Scene& scene, const std::string& name, const std::string& action,
                      const std::string& file) {
    // Edits not saved, replaced (not at the start: the first scene replaces nothing of the user's).
    std::string replaced;
    if (e.doc.revision != 0 && unsaved(e.doc)) {
        replaced = e.doc.name;
        e.session.replaced_unsaved = saved_key(e.doc);
    }
    auto content = std::make_shared<DocumentContent>();
    content->scene = scene;
    content->camera_home = scene.camera;
    content->name = name;
    content->file = file;  // in the step: a redo of a load has its file again
    content->material_b = scene.objects.empty() ? e.doc.material_b : scene.objects[0].material;
    content->b_edited = false;
    edit_document(e, {DocumentEdit{content_of(e.doc), std::move(content)}, action.empty() ? "load " + name : action});
    e.view.selected_object = 0;
    e.view.selected_light = 0;
    return replaced;
}

std::string replaced_note(const std::string& replaced) {
    return replaced.empty() ? "" : "; the unsaved edits of " + replaced + " are one Ctrl+Z back";
}

bool apply(Explorer& e, const command::LoadScene& c) {
    Messages& messages = e.session.messages;
    Scene scene;
    try {
        scene = load_scene_file(c.path, LoadContext::trusted());
    } catch (const std::exception& error) {  // SceneError names file and JSON path
        messages.error = messages.load_error = error.what();
        if (c.error_dialog) e.view.dialog = Dialog::load_error;
        return false;
    }
    const std::string replaced = set_scene(e, scene, c.path, "", c.path);
    mark_saved(e.doc);
    e.session.files.save_dir = std::filesystem::path(c.path).parent_path().string();
    messages.status = "loaded " + c.path + replaced_note(replaced);
    messages.error.clear();
    messages.load_error.clear();
    return true;
}

bool apply(Explorer& e, const command::LoadFigure& c) {
    for (const FigureScene& figure : figure_scenes()) {
        if (figure.name != c.name) continue;
        try {
            const std::string source = "scenes/" + c.name + ".json";
            // Built in: no file of its own, unsaved once edited; Ctrl+S asks
            // where to save (proposing NAME.json, never the file of the scene it replaced).
            const std::string replaced =
                set_scene(e, scene_from_json(nlohmann::json::parse(figure.json), source, LoadContext::trusted()),
                          kPresetName + c.name, "figure preset " + c.name);
            mark_saved(e.doc);
            e.session.messages.status = "figure preset " + c.name + replaced_note(replaced);
            e.session.messages.error.clear();
            return true;
        } catch (const std::exception& error) {
            e.session.messages.error = error.what();
            return false;
        }
    }
    e.session.messages.error = "no figure preset named '" + c.name + "'";
    return false;
}

namespace {

// The text of scene file `path` (Save, a screenshot's JSON): .brdf files
// named as the platform asks (Platform::brdf_paths_relative_to); model files
// so too on the page, and on the desktop from the scene file's own folder.
std::string scene_file_text(const Explorer& e, const std::string& path) {
    const std::string& folder = e.session.platform.brdf_paths_relative_to;
    PathWriting writing{folder, folder};
    if (folder.empty()) writing.model_files_relative_to = std::filesystem::absolute(path).parent_path().string();
    return scene_text(scene_to_json(e.doc.scene, writing));
}

std::string full_path(const std::string& path) {
    std::error_code ec;
    const auto full = std::filesystem::absolute(path, ec);
    return ec ? path : full.lexically_normal().string();  // "/dir/./a.png" reads as /dir/a.png
}

}  // namespace

bool apply(Explorer& e, const command::SaveTo& c) {
    try {
        const std::string text = scene_file_text(e, c.path);
        write_file_atomic(c.path, text.data(), text.size());
        if (e.session.platform.file_written) e.session.platform.file_written(c.path);
        explore::commit_edits(e.doc);  // the edits before the save are a step; the save itself is none
        e.doc.file = c.path;
        e.doc.name = std::filesystem::path(c.path).filename().string();
        mark_saved(e.doc);
        if (saved_key(e.doc) == e.session.replaced_unsaved) e.session.replaced_unsaved.clear();
        e.session.files.overwrite_warned.clear();
        e.session.files.save_dir = std::filesystem::path(c.path).parent_path().string();
        e.session.messages.status = "saved " + full_path(c.path);
        return true;
    } catch (const std::exception& error) {
        e.session.messages.error = error.what();
        return false;
    }
}

bool apply(Explorer& e, const command::Save&) {
    if (e.doc.file.empty()) return apply(e, command::AskSaveAs{});
    return apply(e, command::SaveTo{e.doc.file});
}

namespace {
// A preset's own name ("fig05" for "preset fig05"), "" for any other document.
std::string preset_of(const Document& doc) {
    return doc.name.rfind(kPresetName, 0) == 0 ? doc.name.substr(kPresetName.size()) : "";
}
}  // namespace

std::string save_as_proposal(const Explorer& e) {
    namespace fs = std::filesystem;
    if (!e.doc.file.empty()) return e.doc.file;
    const std::string preset = preset_of(e.doc);
    const fs::path name = preset.empty() ? fs::path(e.session.files.save_name) : fs::path(preset + ".json");
    const std::string& dir = e.session.files.save_dir;
    const fs::path first = dir.empty() ? name : fs::path(dir) / name;
    // A preset's: never a file that exists (the last file's folder may be the
    // repository's scenes/, which holds the presets' own files): NAME-2.json,
    // -3, ... (A practice's submission.json keeps its name: that is the file to hand in.)
    std::error_code ec;
    fs::path proposal = first;
    for (int n = 2; !preset.empty() && fs::exists(proposal, ec); ++n)
        proposal = first.parent_path() / (first.stem().string() + "-" + std::to_string(n) + first.extension().string());
    return proposal.string();
}

bool apply(Explorer& e, const command::AskSaveAs&) {
    e.view.save_path = save_as_proposal(e);
    e.view.save_as_error.clear();
    e.session.files.overwrite_warned.clear();
    e.view.dialog = Dialog::save_as;
    return true;
}

bool apply(Explorer& e, const command::SaveAs& c) {
    std::error_code ec;
    const bool own = !e.doc.file.empty() && std::filesystem::equivalent(c.path, e.doc.file, ec);
    if (!own && std::filesystem::exists(c.path, ec) && e.session.files.overwrite_warned != c.path) {
        e.session.files.overwrite_warned = c.path;
        e.session.messages.error = c.path + " exists and is not this scene's file: Save again to overwrite it";
        return false;
    }
    return apply(e, command::SaveTo{c.path});
}

std::string next_screenshot_path(const Explorer& e) {
    namespace fs = std::filesystem;
    const std::string preset = preset_of(e.doc);
    const std::string stem = !e.doc.file.empty() ? fs::path(e.doc.file).stem().string() : preset.empty() ? "m3055" : preset;
    const std::string& folder = e.session.files.screenshot_dir;
    const fs::path dir = folder.empty() ? fs::path(".") : fs::path(folder);
    for (int n = 1;; ++n) {
        char number[16];
        std::snprintf(number, sizeof number, "-%04d", n);
        const fs::path png = dir / (stem + number + ".png"), json = dir / (stem + number + ".json");
        std::error_code ec;
        const auto& taken = e.session.platform.name_taken;
        if (taken && (taken(png.filename().string()) || taken(json.filename().string()))) continue;
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
bool take_screenshot(Explorer& e, Renderer& renderer, const std::string& path, bool shows_render) {
    const std::string png = path.empty() ? next_screenshot_path(e) : path;
    bool drawn = shows_render;
    try {
        if (!shows_render) {
            // The screenshot waits for the specialized program (as `m3055 render` uses);
            // the explorer's own settings come back however the render ends.
            struct Restore {
                Renderer& renderer;
                bool deferring;
                AreaSampling sampling;
                ~Restore() {
                    renderer.set_defer_compiles(deferring);
                    renderer.set_area_sampling(sampling);
                }
            } restore{renderer, renderer.defers_compiles(), renderer.area_sampling()};
            renderer.set_defer_compiles(false);
            renderer.set_area_sampling(kRenderSampling);
            renderer.render(e.doc.scene);
            drawn = true;
        }
        write_png(png, renderer.read_display());
        const std::string json = json_beside(png), text = scene_file_text(e, json);
        write_file_atomic(json, text.data(), text.size());
        if (e.session.platform.file_written) {
            e.session.platform.file_written(png);
            e.session.platform.file_written(json);
        }
        const std::string full = full_path(png);
        // The JSON by its extension: the path once is what fits the statistics' column at 1280 x 720.
        e.session.messages.status = "screenshot " + full + " + " + std::filesystem::path(json).extension().string();
    } catch (const std::exception& error) {
        e.session.messages.error = error.what();
    }
    return drawn;
}

}  // namespace m3055::explore
