#include "explore/state.h"

#include "explore/figure_scenes.h"
#include "explore/shape_editor.h"
#include "geometry/mesh.h"
#include "image/image.h"
#include "io/message_text.h"
#include "models/model_table.h"
#include "scene/load.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

namespace m3055::explore {

Snapshot snapshot(const ExplorerState& state) {
    return {state.scene, scene_to_json(state.scene), state.material_b, state.camera_home, state.scene_name,
            state.scene_file};
}

void restore(ExplorerState& state, const Snapshot& s) {
    state.scene = s.scene;
    state.material_b = s.material_b;
    state.camera_home = s.camera_home;
    state.scene_name = s.scene_name;
    state.scene_file = s.scene_file;
    selected_material(state);  // clamps the selection
    state.selected_light =
        std::clamp(state.selected_light, 0, std::max(0, static_cast<int>(state.scene.lights.size()) - 1));
    state.changed();
}

void start_history(ExplorerState& state) {
    state.history.reset(snapshot(state));
    state.pending_label.clear();
    state.clean_doc = state.history.head().doc;
    state.clean_file = state.scene_file;
}

bool commit_edits(ExplorerState& state) {
    const bool added = state.history.commit(snapshot(state), state.pending_label);
    state.pending_label.clear();
    return added;
}

bool undo(ExplorerState& state) {
    commit_edits(state);  // an edit still in progress is a step of its own
    if (!state.history.can_undo()) return false;
    state.status = "undid " + state.history.undo_label();
    restore(state, state.history.undo());
    return true;
}

bool redo(ExplorerState& state) {
    commit_edits(state);
    if (!state.history.can_redo()) return false;
    state.status = "redid " + state.history.redo_label();
    restore(state, state.history.redo());
    return true;
}

bool unsaved(const ExplorerState& state) {
    return state.scene_file != state.clean_file || scene_to_json(state.scene) != state.clean_doc;
}

std::string title_name(const ExplorerState& state) {
    return state.scene_name + (unsaved(state) ? " * (unsaved edits)" : "");
}

void set_scene(ExplorerState& state, const Scene& scene, const std::string& name) {
    state.pending_label = "load " + name;
    state.scene = scene;
    state.camera_home = scene.camera;
    state.scene_name = name;
    state.selected_object = 0;
    state.selected_light = 0;
    if (!scene.objects.empty()) state.material_b = scene.objects[0].material;
    state.changed();
}

bool load_scene(ExplorerState& state, const std::string& path) {
    try {
        set_scene(state, load_scene_file(path), path);
        state.scene_file = state.clean_file = path;
        state.clean_doc = scene_to_json(state.scene);
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
            set_scene(state, scene_from_json(nlohmann::json::parse(figure.json), source), source);
            // Built in: nothing to lose yet (digit keys may flip through the
            // figures); Ctrl+S asks where to save.
            state.scene_file.clear();
            state.clean_file.clear();
            state.clean_doc = scene_to_json(state.scene);
            state.pending_label = "figure preset " + name;
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

bool save_scene(ExplorerState& state, const std::string& path) {
    try {
        const std::string text = scene_to_json(state.scene).dump(2) + "\n";
        write_file_atomic(path, text.data(), text.size());
        state.scene_file = state.clean_file = path;
        state.clean_doc = scene_to_json(state.scene);
        state.scene_name = std::filesystem::path(path).filename().string();
        commit_edits(state);  // the edits before the save are a step; the save itself is none
        state.history.set_head_file(state.scene_name, path);
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
    if (state.scene_file.empty()) state.save_as_requested = true;
    else save_scene(state, state.scene_file);
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

Material* selected_material(ExplorerState& state) {
    if (state.scene.objects.empty()) return nullptr;
    state.selected_object =
        std::clamp(state.selected_object, 0, static_cast<int>(state.scene.objects.size()) - 1);
    return &state.scene.objects[state.selected_object].material;
}

std::vector<const ModelSpec*> all_models() {
    std::vector<const ModelSpec*> models;
    for (const ModelSpec& model : model_table().models()) models.push_back(&model);
    return models;
}

void set_model(Material& material, const ModelSpec& model) { material = with_model(material, model); }

void set_model(Material& material, const std::string& model_name) {
    const ModelSpec* model = model_table().find(model_name);
    if (!model) throw std::runtime_error("unknown model '" + model_name + "'");
    set_model(material, *model);
}

void apply_light_preset(ExplorerState& state, LightPreset preset) {
    state.scene.lights = light_preset(preset);
    state.pending_label = "light preset";
    state.selected_light = 0;
    state.changed();
}

std::string valid_light_name(const std::string& typed) {
    std::string kept;
    for (char c : typed)
        if (static_cast<unsigned char>(c) >= 0x20 && c != 0x7F) kept += c;
    if (kept.size() > 64) kept.resize(64);
    while (!kept.empty() && !text::is_valid_utf8(kept)) kept.pop_back();  // a cut multi-byte character
    return kept;
}

bool add_light(ExplorerState& state) {
    if (static_cast<int>(state.scene.lights.size()) >= kMaxExplorerLights) return false;
    state.scene.lights.push_back(light_preset(LightPreset::single_key)[0]);
    state.pending_label = "add light";
    state.selected_light = static_cast<int>(state.scene.lights.size()) - 1;
    state.changed();
    return true;
}

bool remove_light(ExplorerState& state, int index) {
    auto& lights = state.scene.lights;
    if (index < 0 || index >= static_cast<int>(lights.size())) return false;
    lights.erase(lights.begin() + index);
    state.pending_label = "remove light " + std::to_string(index);
    state.selected_light = std::clamp(state.selected_light, 0, std::max(0, static_cast<int>(lights.size()) - 1));
    state.changed();
    return true;
}

void add_object(ExplorerState& state, Shape shape) {
    Object sphere;
    if (Material* material = selected_material(state)) sphere.material = *material;
    // Beside the right-most object (not counting floors), so the new one is
    // visible and does not overlap.
    double right = -1e300;
    for (const Object& o : state.scene.objects)
        if (o.shape != Shape::plane) right = std::max(right, o.center.x + geometry::bounding_radius(o));
    if (right > -1e300) sphere.center = {right + 0.25 + sphere.radius, 0.0, 0.0};
    if (shape == Shape::plane) {  // a floor under everything
        double bottom = 0.0, reach = 1.0;
        for (const Object& o : state.scene.objects) {
            if (o.shape == Shape::plane) continue;
            bottom = std::min(bottom, o.center.y - geometry::bounding_radius(o));
            reach = std::max(reach, std::abs(o.center.x) + geometry::bounding_radius(o));
        }
        sphere.center = {0.0, bottom, 0.0};
        sphere.shape = Shape::plane;
        sphere.size = 4.0 * reach;
    }
    set_shape(sphere, shape);
    state.scene.objects.push_back(sphere);
    state.pending_label = std::string("add ") + to_string(shape);
    state.selected_object = static_cast<int>(state.scene.objects.size()) - 1;
    state.changed();
}

bool remove_object(ExplorerState& state, int index) {
    auto& objects = state.scene.objects;
    if (objects.size() <= 1 || index < 0 || index >= static_cast<int>(objects.size())) return false;
    objects.erase(objects.begin() + index);
    state.pending_label = "remove object " + std::to_string(index);
    selected_material(state);  // clamps the selection
    state.changed();
    return true;
}

void set_display_m3055(ExplorerState& state) {
    state.scene.display.width = 512;
    state.scene.display.height = 320;
    state.scene.display.bits = 5;
    state.changed();
}

void set_display_modern(ExplorerState& state, int width, int height) {
    state.scene.display.width = std::clamp(width, 1, kMaxDisplaySize);
    state.scene.display.height = std::clamp(height, 1, kMaxDisplaySize);
    state.scene.display.bits = 8;
    state.scene.display.dither = false;
    state.changed();
}

namespace {
// Rodrigues' rotation of v by `angle` radians about the unit axis k.
dvec3 rotate(const dvec3& v, double angle, const dvec3& k) {
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1.0 - c);
}

// Radians of orbit per pixel dragged: a 300-pixel drag turns about 90 degrees.
constexpr double kOrbitPerPixel = 0.3 * 3.14159265358979323846 / 180.0;
// Keep the view direction at least this far (radians) from `up` (docs/spec.md#7-scene-files).
constexpr double kPoleMargin = 0.02;
// One wheel step moves 10 % closer.
constexpr double kZoomPerStep = 0.9;
}  // namespace

void orbit_camera(ExplorerState& state, double dx_pixels, double dy_pixels) {
    Camera& c = state.scene.camera;
    const dvec3 up = glm::normalize(c.up);
    dvec3 offset = c.position - c.target;
    // Dragging right turns the camera left around the object (the object seems to turn right).
    offset = rotate(offset, -dx_pixels * kOrbitPerPixel, up);
    // Dragging down raises the camera, clamped short of the poles.
    const double radius = glm::length(offset);
    const double polar = std::acos(std::clamp(glm::dot(offset / radius, up), -1.0, 1.0));
    const double wanted = std::clamp(polar - dy_pixels * kOrbitPerPixel, kPoleMargin,
                                     3.14159265358979323846 - kPoleMargin);
    const dvec3 right = glm::normalize(glm::cross(offset, up));
    offset = rotate(offset, polar - wanted, right);
    c.position = c.target + offset;
    state.changed();
}

void zoom_camera(ExplorerState& state, double wheel_steps) {
    Camera& c = state.scene.camera;
    const double factor = std::pow(kZoomPerStep, wheel_steps);
    if (c.projection == Projection::orthographic) {
        c.height = std::clamp(c.height * factor, 1e-3, 1e4);
    } else {
        const dvec3 offset = c.position - c.target;
        const double distance = std::clamp(glm::length(offset) * factor, 1e-2, 1e4);
        c.position = c.target + glm::normalize(offset) * distance;
    }
    state.changed();
}

void reset_camera(ExplorerState& state) {
    state.scene.camera = state.camera_home;
    state.changed();
}

void set_compare(ExplorerState& state, bool on) {
    state.compare = on;
    state.changed();
}

void copy_a_to_b(ExplorerState& state) {
    if (const Material* a = selected_material(state)) state.material_b = *a;
    state.pending_label = "B = copy of A";
    state.changed();
}

Scene compare_scene(const ExplorerState& state) {
    Scene b = state.scene;
    if (!b.objects.empty()) {
        const int i = std::clamp(state.selected_object, 0, static_cast<int>(b.objects.size()) - 1);
        b.objects[i].material = state.material_b;
    }
    return b;
}

}  // namespace m3055::explore
