// Scene files (SPEC section 7) -> validated Scene. Every check goes through
// scene_json::Node so that each error is one line "SOURCE: json.path: problem".
#include "scene/load.h"

#include "geometry/mesh.h"
#include "scene/json_classic.h"
#include "scene/json_node.h"
#include "scene/json_parse.h"
#include "scene/json_shapes.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace m3055 {

using scene_json::closed;
using scene_json::json;
using scene_json::kCoordinate;
using scene_json::kUnit;
using scene_json::Node;
using scene_json::Range;

namespace {

constexpr std::size_t kMaxObjects = 100000;

const Range kLobeWeight = closed(0.0, 100.0);
const Range kBeckmannM = closed(0.001, 2.0);
const Range kExponent = closed(0.0, 10000.0);  // highlight m, lobe n, spot exponent

// ---- display ----------------------------------------------------------------

Display read_display(const Node& node) {
    node.expect_object();
    node.check_keys({"width", "height", "bits", "dither"});
    Display display;
    if (node.has("width")) display.width = node.child("width").whole_in(1, kMaxDisplaySize);
    if (node.has("height")) display.height = node.child("height").whole_in(1, kMaxDisplaySize);
    if (node.has("bits")) display.bits = node.child("bits").whole_in(1, 8);
    if (node.has("dither")) display.dither = node.child("dither").boolean();
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

// ---- lobes ------------------------------------------------------------------

// Material lobes: every entry {"w", key} where key is "m" (metal) or "n".
std::vector<Lobe> read_material_lobes(const Node& node, Model model) {
    const bool beckmann = model == Model::metal;
    return read_lobe_list(node, beckmann ? "m" : "n", beckmann ? "n" : "m", kLobeWeight,
                          beckmann ? kBeckmannM : kExponent, std::string("model ") + to_string(model));
}

// A light's own lobes: all Beckmann {"w","m"} or all exponent {"w","n"}.
void read_light_lobes(const Node& node, Light& light) {
    const std::size_t count = node.array_size(1, kMaxLobes, "1 to 4 lobes");
    for (std::size_t i = 0; i < count; ++i) {
        const Node entry = node.at(i);
        entry.expect_object();
        entry.check_keys({"w", "m", "n"});
        if (entry.has("m") == entry.has("n")) entry.fail("must have exactly one of \"m\" and \"n\"");
        const LobeKind kind = entry.has("m") ? LobeKind::beckmann : LobeKind::exponent;
        const std::string key = kind == LobeKind::beckmann ? "m" : "n";
        if (i == 0) {
            light.lobe_kind = kind;
        } else if (kind != light.lobe_kind) {
            entry.child(key).fail("all lobes of a light must use the same key (lobes[0] uses \"" +
                                  std::string(kind == LobeKind::beckmann ? "n" : "m") + "\")");
        }
        Lobe lobe;
        lobe.w = entry.required("w").number_in(kLobeWeight);
        lobe.m = entry.child(key).number_in(kind == LobeKind::beckmann ? kBeckmannM : kExponent);
        light.lobes.push_back(lobe);
    }
}

// ---- lights -----------------------------------------------------------------

void read_attenuation(const Node& node, Light& light) {
    const json& value = node.value();
    if (value.is_string()) {
        const std::size_t which = node.one_of({"constant", "inverse", "physical"});
        light.att_constant = which == 0 ? 1.0 : 0.0;
        light.att_linear = which == 1 ? 1.0 : 0.0;
        light.att_quadratic = which == 2 ? 1.0 : 0.0;
        return;
    }
    if (!value.is_array() || value.size() != 3 ||
        !std::all_of(value.begin(), value.end(), [](const json& e) { return e.is_number(); }))
        node.fail("must be an array of 3 numbers [S_c, S_l, S_q] or \"constant\", \"inverse\" or \"physical\"");
    const dvec3 s = node.vec3_in(closed(0.0, 1e6));
    if (s.x == 0.0 && s.y == 0.0 && s.z == 0.0) node.fail("must not be all zero");
    light.att_constant = s.x;
    light.att_linear = s.y;
    light.att_quadratic = s.z;
}

Light read_light(const Node& node) {
    node.expect_object();
    Light light;
    const std::size_t type = node.required("type").one_of({"directional", "point", "spot"});
    light.type = type == 0 ? LightType::directional : type == 1 ? LightType::point : LightType::spot;
    std::vector<std::string> allowed = {"type", "intensity", "color", "enabled", "lobes", "ambient"};
    if (light.type == LightType::directional) allowed.push_back("direction");
    if (light.type != LightType::directional) allowed.insert(allowed.end(), {"position", "attenuation"});
    if (light.type == LightType::spot) allowed.insert(allowed.end(), {"spot_direction", "spot_exponent"});
    node.check_keys(allowed, [](const std::string& key) {
        if (key == "direction") return std::string("only for directional lights");
        if (key == "position" || key == "attenuation") return std::string("only for point and spot lights");
        if (key == "spot_direction" || key == "spot_exponent") return std::string("only for spot lights");
        return std::string();
    });

    if (light.type == LightType::directional) {
        light.direction = node.required("direction").direction();
    } else {
        light.position = node.required("position").vec3_in(kCoordinate);
        if (node.has("attenuation")) read_attenuation(node.child("attenuation"), light);
    }
    if (light.type == LightType::spot) {
        light.spot_direction = node.required("spot_direction").direction();
        if (node.has("spot_exponent")) light.spot_exponent = node.child("spot_exponent").number_in(kExponent);
    }
    if (node.has("intensity")) light.intensity = node.child("intensity").number_in(closed(0.0, 10.0));
    if (node.has("color")) light.color = node.child("color").vec3_in(kUnit);
    if (node.has("enabled")) light.enabled = node.child("enabled").boolean();
    if (node.has("ambient")) light.ambient = node.child("ambient").vec3_in(kUnit);  // classic models
    if (node.has("lobes")) read_light_lobes(node.child("lobes"), light);
    return light;
}

// ---- materials and objects --------------------------------------------------

const std::vector<std::string>& model_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> all = {"highlight", "translucent", "metal", "metal_blinn", "metal_phong"};
        const auto& classic = scene_json::classic_model_names();  // SPEC 5, in Model's order
        all.insert(all.end(), classic.begin(), classic.end());
        return all;
    }();
    return names;
}

// The keys each model reads, besides "model" and "color".
std::vector<std::string> model_keys(Model model) {
    switch (model) {
        case Model::highlight: return {"d", "w", "m"};
        case Model::translucent: return {"d", "w", "m", "t_n", "t_p"};
        case Model::metal:
        case Model::metal_blinn:
        case Model::metal_phong: return {"d", "lobes"};
        default: break;  // the classic models: scene/json_classic.cpp
    }
    return {};
}

// The paper's defaults for each model (SPEC 4, Fig. 10).
Material default_material(Model model) {
    Material material;
    material.model = model;
    if (uses_lobes(model)) material.d = 0.05;
    if (model == Model::metal) material.lobes = {{0.013, 0.2}, {0.1, 0.4}};
    if (model == Model::metal_blinn) material.lobes = {{1.0, 13.0}};
    if (model == Model::metal_phong) material.lobes = {{1.0, 20.0}};
    return material;
}

Material read_material(const Node& node) {
    node.expect_object();
    const Model model = static_cast<Model>(node.required("model").one_of(model_names()));
    if (is_classic(model)) return scene_json::read_classic_material(node, model);
    std::vector<std::string> allowed = model_keys(model);
    allowed.insert(allowed.end(), {"model", "color"});
    const std::string problem = std::string("not a parameter of model ") + to_string(model);
    node.check_keys(allowed, [&](const std::string& key) {
        for (const std::string& known : model_keys(Model::translucent)) if (key == known) return problem;
        return key == "lobes" || scene_json::is_classic_material_key(key) ? problem : std::string();
    });

    Material material = default_material(model);
    material.color = node.required("color").vec3_in(kUnit);
    if (node.has("d")) material.d = node.child("d").number_in(kUnit);
    if (node.has("w")) material.w = node.child("w").number_in(kUnit);
    if (node.has("m")) material.m = node.child("m").number_in(kExponent);
    if (node.has("t_n")) material.t_n = node.child("t_n").number_in(kUnit);
    if (node.has("t_p")) material.t_p = node.child("t_p").number_in(closed(0.0, 10.0));
    if (node.has("lobes")) material.lobes = read_material_lobes(node.child("lobes"), model);
    return material;
}

Object read_object(const Node& node) {
    node.expect_object();
    Object object;
    scene_json::read_shape(node, object);  // shape, centre and the shape's own keys
    object.material = read_material(node.required("material"));
    return object;
}

// ---- files ------------------------------------------------------------------

std::string read_file(const std::string& path) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) throw SceneError(path + ": cannot read file: " + std::strerror(errno));
    std::string text;
    char buffer[65536];
    std::size_t got = 0;
    while ((got = std::fread(buffer, 1, sizeof buffer, file)) > 0) text.append(buffer, got);
    const bool failed = std::ferror(file) != 0;
    const int error = errno;  // e.g. EISDIR: fopen of a folder succeeds, reading fails
    std::fclose(file);
    if (failed) throw SceneError(path + ": cannot read file: " + std::strerror(error));
    return text;
}

}  // namespace

Scene scene_from_json(const json& doc, const std::string& source) {
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
        for (std::size_t i = 0; i < count; ++i) scene.lights.push_back(read_light(lights.at(i)));
    }
    const Node objects = root.required("objects");
    const std::size_t count = objects.array_size(0, kMaxObjects, "at most 100000 objects");
    scene.objects.reserve(count);
    std::size_t triangles = 0;
    for (std::size_t i = 0; i < count; ++i) {
        scene.objects.push_back(read_object(objects.at(i)));
        // Bounded so that no scene file can exhaust memory with meshes.
        triangles += geometry::triangle_count(scene.objects.back());
        if (triangles > geometry::kMaxSceneTriangles)
            objects.at(i).fail("the scene's meshes would have more than " +
                               std::to_string(geometry::kMaxSceneTriangles) + " triangles (fewer segments?)");
    }
    return scene;
}

Scene load_scene_file(const std::string& path, const std::vector<Override>& overrides) {
    const std::string text = read_file(path);
    json doc = scene_json::parse_document(text, path);
    apply_overrides(doc, overrides, path);
    return scene_from_json(doc, path);
}

}  // namespace m3055
