// Scene files (docs/spec.md#7-scene-files) -> validated Scene. Every check goes through
// scene_json::Node so that each error is one line "SOURCE: json.path: problem".
#include "scene/load.h"

#include "io/input_file.h"
#include "io/message_text.h"
#include "scene/json_lights.h"
#include "scene/json_material.h"
#include "scene/json_model_file.h"
#include "scene/json_node.h"
#include "scene/json_parse.h"
#include "scene/json_shapes.h"
#include "scene/referenced_file.h"
#include "scene/shape_limits.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace m3055 {

using scene_json::closed;
using scene_json::json;
using scene_json::kCoordinate;
using scene_json::kUnit;
using scene_json::Node;
using scene_json::Range;

namespace {

constexpr std::size_t kMaxObjects = 100000;

// ---- display ----------------------------------------------------------------

Display read_display(const Node& node) {
    node.expect_object();
    node.check_keys({"width", "height", "bits", "dither", "view_transform"});
    Display display;
    if (node.has("width")) display.width = node.child("width").whole_in(1, kMaxDisplaySize);
    if (node.has("height")) display.height = node.child("height").whole_in(1, kMaxDisplaySize);
    if (node.has("bits")) display.bits = node.child("bits").whole_in(1, 8);
    if (node.has("dither")) display.dither = node.child("dither").boolean();
    if (node.has("view_transform"))
        display.view_transform = node.child("view_transform").one_of({"none", "srgb"}) == 0 ? ViewTransform::none
                                                                                           : ViewTransform::srgb;
    return display;
}

// ---- camera -----------------------------------------------------------------

double length_of(const dvec3& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

Camera read_camera(const Node& node) {
    node.expect_object();
    Camera camera;
    camera.projection = node.required("projection").one_of({"perspective", "orthographic"}) == 0
                            ? Projection::perspective
                            : Projection::orthographic;
    const bool perspective = camera.projection == Projection::perspective;
    const std::string own = perspective ? "fov_y_deg" : "height";
    node.check_keys({"projection", "position", "target", "up", own}, [](const std::string& key) {
        if (key == "fov_y_deg") return std::string("only for perspective cameras");
        if (key == "height") return std::string("only for orthographic cameras");
        return std::string();
    });
    camera.position = node.required("position").vec3_in(kCoordinate);
    const Node target = node.required("target");
    camera.target = target.vec3_in(kCoordinate);
    if (perspective)
        camera.fov_y_deg = node.required("fov_y_deg").number_in(Range{0.0, 180.0, true, true});
    else
        // Bounded like coordinates: height * aspect must stay finite in every renderer.
        camera.height = node.required("height").number_in(Range{0.0, 1e6, true, false});

    // Coordinates are within 1e6, so the difference and its length cannot overflow;
    // 1e-9 keeps normalize(target - position) away from underflow in every renderer.
    const dvec3 view = camera.target - camera.position;
    if (length_of(view) < 1e-9) target.fail("must differ from camera.position");
    // The default up is checked like a given one, so a camera looking straight down
    // without "up" is an error on camera.up rather than a NaN basis.
    static const json kDefaultUp = json::array({0, 1, 0});
    const Node up = node.has("up") ? node.child("up")
                                   : Node(kDefaultUp, scene_json::join_key(node.path(), "up"), node.source());
    if (node.has("up")) camera.up = up.direction();
    const dvec3 f = scene_json::unit_vector(view);
    if (length_of(glm::cross(f, camera.up)) < 1e-6)  // both unit: |f x up| = sin(angle)
        up.fail(node.has("up") ? "must not be parallel to the view direction"
                               : "must not be parallel to the view direction (default [0, 1, 0])");
    return camera;
}

// ---- objects (materials: scene/json_material.cpp) ---------------------------

Object read_object(const Node& node, const scene_json::SceneFiles& files) {
    node.expect_object();
    Object object;
    scene_json::read_shape(node, object);  // shape, centre and the shape's own keys
    if (object.shape == Shape::mesh)
        scene_json::read_mesh_file(node, files, object);  // the model file and its materials
    else
        object.material = scene_json::read_material(node.required("material"), files);
    return object;
}

// A scene whose named files are found as `files` says.
Scene read_scene(const json& doc, const std::string& source, const scene_json::SceneFiles& files) {
    const Node root(doc, "", source);
    root.expect_object();
    root.check_keys({"display", "background", "ambient", "camera", "lights", "objects"});
    Scene scene;
    if (root.has("display")) scene.display = read_display(root.child("display"));
    if (root.has("background")) scene.background = root.child("background").vec3_in(kUnit);
    if (root.has("ambient")) scene.ambient = root.child("ambient").vec3_in(kUnit);  // L_glob, classic models
    scene.camera = read_camera(root.required("camera"));
    if (root.has("lights")) {
        const Node lights = root.child("lights");
        const std::size_t count = lights.array_size(0, kMaxLights, "at most 16 lights");
        for (std::size_t i = 0; i < count; ++i) scene.lights.push_back(scene_json::read_light(lights.at(i)));
    }
    const Node objects = root.required("objects");
    const std::size_t count = objects.array_size(0, kMaxObjects, "at most 100000 objects");
    scene.objects.reserve(count);
    std::size_t triangles = 0;
    for (std::size_t i = 0; i < count; ++i) {
        scene.objects.push_back(read_object(objects.at(i), files));
        // Bounded so that no scene file can exhaust memory with meshes.
        triangles += triangle_count(scene.objects.back());
        if (triangles > kMaxSceneTriangles)
            objects.at(i).fail("the scene's meshes would have more than " +
                               std::to_string(kMaxSceneTriangles) + " triangles (" +
                               (scene.objects.back().shape == Shape::mesh ? "a smaller model?)" : "fewer segments?)"));
    }
    return scene;
}

// `doc` with `overrides` applied, read; a problem a --set made is blamed on it.
Scene read_overridden_scene(json doc, const std::vector<Override>& overrides, const std::string& source,
                            const scene_json::SceneFiles& files) {
    apply_overrides(doc, overrides, source);
    try {
        return read_scene(doc, source, files);
    } catch (const SceneError& error) {
        if (overrides.empty()) throw;
        throw blame_override(error, overrides, source);
    }
}

}  // namespace

Scene scene_from_json(const json& doc, const std::string& source, const LoadContext& context) {
    return read_scene(doc, source, {context, ""});
}

Scene scene_from_json(json doc, const std::vector<Override>& overrides, const std::string& source,
                      const LoadContext& context) {
    return read_overridden_scene(std::move(doc), overrides, source, {context, ""});
}

Scene load_scene_file(const std::string& path, const LoadContext& context, const std::vector<Override>& overrides) {
    // The file name as every message shows it: quoted with escapes when it
    // holds a newline or invalid UTF-8, its middle cut when long.
    const std::string source = text::quote_name(path);
    json doc;
    try {
        doc = scene_json::parse_document(io::read_input_file(io::InputPath::in_folder(context.folder, path)), source);
    } catch (const io::InputError& error) {
        throw SceneError(error.what());
    }
    // The files the scene names are relative to its folder.
    return read_overridden_scene(std::move(doc), overrides, source,
                                 {context, std::filesystem::path(path).parent_path().string()});
}

}  // namespace m3055
