#include "explore/add_model.h"

#include "explore/brdf_files.h"
#include "explore/operations.h"
#include "geometry/mesh.h"
#include "scene/load.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>

namespace m3055::explore {

namespace {

constexpr double kViewFraction = 0.4;  // the model's largest side, of the view's height at the target
constexpr double kInsideView = 0.8;    // its middle within this much of the view's half-width and half-height

double view_height_at_target(const Camera& camera) {
    if (camera.projection == Projection::orthographic) return camera.height;
    const double distance = glm::length(camera.target - camera.position);
    return 2.0 * distance * std::tan(glm::radians(camera.fov_y_deg) * 0.5);
}

struct CameraBasis {
    dvec3 forward, right, up;
};

CameraBasis basis_of(const Camera& camera) {
    const dvec3 forward = glm::normalize(camera.target - camera.position);
    dvec3 right = glm::cross(forward, camera.up);
    right = glm::length(right) > 1e-12 ? glm::normalize(right) : dvec3(1.0, 0.0, 0.0);
    return {forward, right, glm::cross(right, forward)};
}

// Whether `point` is in the middle of the view (by kInsideView).
bool well_inside_view(const Scene& scene, const CameraBasis& b, const dvec3& point) {
    const Camera& camera = scene.camera;
    const double aspect = double(scene.display.width) / double(std::max(1, scene.display.height));
    const dvec3 v = point - camera.position;
    const double depth = glm::dot(v, b.forward);
    if (depth <= 0.0) return false;
    const double half_h = camera.projection == Projection::orthographic
                              ? camera.height * 0.5
                              : depth * std::tan(glm::radians(camera.fov_y_deg) * 0.5);
    const double x = glm::dot(v, b.right) / (half_h * aspect), y = glm::dot(v, b.up) / half_h;
    return std::abs(x) <= kInsideView && std::abs(y) <= kInsideView;
}

struct Box {
    dvec3 lo, hi;
};

// An object's box in the world: a mesh from a file not rotated, its own;
// anything else the box around its bounding sphere.
Box box_of(const Object& o) {
    if (o.shape == Shape::mesh && o.model && o.rotation_deg == dvec3(0.0)) {
        const dvec3 extent = o.model->hi - o.model->lo;
        const double largest = std::max({extent.x, extent.y, extent.z, 1e-300});
        const dvec3 half = 0.5 * o.size * extent / largest;
        return {o.center - half, o.center + half};
    }
    const double r = geometry::bounding_radius(o);
    return {o.center - dvec3(r), o.center + dvec3(r)};
}

// The volume `box` shares with the other objects' boxes (floors not counted).
double overlap_with_others(const Scene& scene, const Box& box) {
    double volume = 0.0;
    for (const Object& o : scene.objects) {
        if (o.shape == Shape::plane) continue;
        const Box other = box_of(o);
        const dvec3 shared = glm::min(box.hi, other.hi) - glm::max(box.lo, other.lo);
        if (shared.x > 0.0 && shared.y > 0.0 && shared.z > 0.0) volume += shared.x * shared.y * shared.z;
    }
    return volume;
}

// The loader's message without the place it gives in the one-object scene
// made here: "SOURCE: objects[0].file: " (the model file is named after it).
std::string model_problem(const std::string& message, const std::string& source) {
    const std::string prefix = source + ": objects[0].file: ";
    return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
}

}  // namespace

bool is_model_path(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".obj" || extension == ".gltf" || extension == ".glb";
}

double floor_height(const Scene& scene) {
    double floor = 0.0;
    bool found = false;
    for (const Object& o : scene.objects) {
        if (o.shape != Shape::plane || std::abs(o.axis.y) < 0.99) continue;
        floor = found ? std::min(floor, o.center.y) : o.center.y;
        found = true;
    }
    return floor;
}

Object placed_on_floor(const Scene& scene, Object model) {
    const double floor = floor_height(scene);
    const CameraBasis b = basis_of(scene.camera);
    dvec3 across{b.right.x, 0.0, b.right.z};
    across = glm::length(across) > 1e-12 ? glm::normalize(across) : dvec3(1.0, 0.0, 0.0);
    dvec3 toward{-b.forward.x, 0.0, -b.forward.z};  // towards the camera, along the floor
    toward = glm::length(toward) > 1e-12 ? glm::normalize(toward) : dvec3(0.0);
    const double full_size = kViewFraction * view_height_at_target(scene.camera);
    // Smaller where the view is full; where nothing is free, the place in
    // view that overlaps the others least (a model inside another is not in view).
    Object least = model;
    double least_overlap = std::numeric_limits<double>::infinity();
    for (const double shrink : {1.0, 0.75, 0.5}) {
        model.size = full_size * shrink;
        model.center = dvec3(0.0);
        const Box own = box_of(model);
        const dvec3 base{scene.camera.target.x, floor - own.lo.y, scene.camera.target.z};
        // Along the floor's line across the view first, then on lines nearer the camera (in front of the others).
        for (int row = 0; row <= 3; ++row) {
            for (int k = 0; k <= 16; ++k) {
                const double offset = (k % 2 == 1 ? 1.0 : -1.0) * double((k + 1) / 2) * 0.25 * full_size;  // 0, +, -, ...
                model.center = base + across * offset + toward * (0.5 * full_size * row);
                if (!well_inside_view(scene, b, model.center)) continue;
                const double overlap = overlap_with_others(scene, {own.lo + model.center, own.hi + model.center});
                if (overlap <= 0.0) return model;
                if (overlap < least_overlap) least_overlap = overlap, least = model;
            }
        }
    }
    if (least_overlap < std::numeric_limits<double>::infinity()) return least;
    model.size = full_size;
    model.center = dvec3(0.0);
    model.center = {scene.camera.target.x, floor - box_of(model).lo.y, scene.camera.target.z};
    return model;  // nothing of the floor's line in view: at the target
}

Command dropped_file_command(const std::string& path) {
    if (is_brdf_path(path)) return command::OpenBrdf{path};
    if (is_model_path(path)) return command::AddModel{path, true};
    return command::LoadScene{path, true};
}

std::vector<Command> dropped_files_commands(const std::vector<std::string>& paths) {
    const bool with_model = std::any_of(paths.begin(), paths.end(), is_model_path);
    std::vector<Command> commands;
    for (const std::string& path : paths) {
        std::string extension = std::filesystem::path(path).extension().string();
        std::transform(extension.begin(), extension.end(), extension.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (with_model && (extension == ".mtl" || extension == ".bin")) continue;
        commands.push_back(dropped_file_command(path));
    }
    return commands;
}

bool apply(Explorer& e, const command::AddModel& c) {
    Messages& messages = e.session.messages;
    const std::string name = std::filesystem::path(c.path).filename().string();
    const std::string source = "add model";
    Object model;
    try {
        std::error_code ec;
        const std::filesystem::path full = std::filesystem::absolute(c.path, ec);
        Scene around = e.doc.scene;  // the scene's display, camera and lights: a scene the loader takes
        around.objects.clear();
        nlohmann::json doc = scene_to_json(around, PathWriting::absolute());
        doc["objects"] = {{{"shape", "mesh"}, {"file", ec ? c.path : full.string()}, {"center", {0, 0, 0}}, {"size", 1}}};
        model = scene_from_json(doc, source, LoadContext::trusted()).objects.at(0);
    } catch (const std::exception& error) {
        messages.error = messages.load_error = model_problem(error.what(), source);
        if (c.error_dialog) e.view.dialog = Dialog::load_error;
        return false;
    }
    Object placed = placed_on_floor(e.doc.scene, std::move(model));
    const int index = static_cast<int>(e.doc.scene.objects.size());
    edit_document(e, {ObjectInsert{index, std::move(placed)}, "add model " + name});
    e.view.selected_object = index;
    e.view.selected_group = 0;
    messages.status = "added " + c.path + " as object " + std::to_string(index);
    messages.error.clear();
    messages.load_error.clear();
    return true;
}

}  // namespace m3055::explore
