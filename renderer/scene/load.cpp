// Scene files (docs/spec.md#7-scene-files) -> validated Scene. Every check goes through
// scene_json::Node so that each error is one line "SOURCE: json.path: problem".
#include "scene/load.h"

#include "io/input_file.h"
#include "io/message_text.h"
#include "models/model_table.h"
#include "scene/json_material.h"
#include "scene/json_model_file.h"
#include "scene/json_node.h"
#include "scene/json_parse.h"
#include "scene/json_shapes.h"
#include "scene/referenced_file.h"
#include "scene/shape_limits.h"
#include "spectral/blackbody.h"
#include "spectral/cie_data.h"
#include "spectral/colorimetry.h"

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

const Range kExponent = closed(0.0, 10000.0);  // spot exponent

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

// ---- lobes ------------------------------------------------------------------

// A light's own lobes replace the material's for the models that read them
// (ModelSpec::light_lobes), so they have those models' ranges.
const LobeForm& light_lobe_form(LobeKind kind) {
    for (const ModelSpec& spec : model_table().models())
        if (spec.light_lobes == kind) return spec.param("lobes").forms.at(0);
    throw std::logic_error("no model of the table reads light lobes of this kind");
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
        const LobeForm& form = light_lobe_form(kind);
        Lobe lobe;
        lobe.w = entry.required("w").number_in(form.weight);
        lobe.m = entry.child(key).number_in(form.value);
        light.lobes.push_back(lobe);
    }
}

// ---- lights -----------------------------------------------------------------

// A light's "name": 1 to 64 bytes of printable UTF-8.
std::string read_light_name(const Node& node) {
    if (!node.value().is_string()) node.fail("must be a string");
    const std::string& name = node.value().get_ref<const std::string&>();
    if (name.empty() || name.size() > 64) node.fail("must be 1 to 64 bytes long");
    const bool control = std::any_of(name.begin(), name.end(), [](char c) {
        return static_cast<unsigned char>(c) < 0x20 || c == 0x7F;
    });
    if (control || !text::is_valid_utf8(name)) node.fail("must be UTF-8 text without control characters");
    return name;
}

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

// The light's colour: "color" (RGB), "temperature_k" (a black body) or
// "illuminant" (a CIE standard illuminant), at most one of them
// (docs/spec.md#71-spectral-lights). A spectral light's RGB is computed here,
// once, so the GPU and the reference both use it.
void read_light_color(const Node& node, Light& light) {
    const char* given[] = {"color", "temperature_k", "illuminant"};
    std::vector<std::string> present;
    for (const char* key : given)
        if (node.has(key)) present.push_back(key);
    if (present.size() > 1) {
        const std::string who = light.name.empty() ? "this light" : "light " + text::quote(light.name);
        node.child(present[1]).fail(who + " gives both \"" + present[0] + "\" and \"" + present[1] +
                                    "\"; give one colour");
    }
    if (node.has("color")) {
        light.color = node.child("color").vec3_in(kUnit);
        return;
    }
    if (!node.has("temperature_k") && !node.has("illuminant")) return;
    const Node source = node.child(present[0]);
    try {
        if (node.has("temperature_k")) {
            light.temperature_k = source.number_in(closed(spectral::kMinKelvin, spectral::kMaxKelvin));
            light.color = spectral::temperature_rgb(light.temperature_k);
        } else {
            light.illuminant = spectral::illuminant_names()[source.one_of(spectral::illuminant_names())];
            light.color = spectral::illuminant_rgb(light.illuminant);
        }
    } catch (const spectral::SpectralError& error) {
        source.fail(std::string("cannot make its colour: ") + error.what());
    }
}

Light read_light(const Node& node) {
    node.expect_object();
    Light light;
    const std::size_t type = node.required("type").one_of({"directional", "point", "spot"});
    light.type = type == 0 ? LightType::directional : type == 1 ? LightType::point : LightType::spot;
    std::vector<std::string> allowed = {"name",    "type",  "intensity", "color",        "temperature_k",
                                        "illuminant", "enabled", "lobes",    "ambient"};
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
    if (node.has("name")) light.name = read_light_name(node.child("name"));
    read_light_color(node, light);
    if (node.has("enabled")) light.enabled = node.child("enabled").boolean();
    if (node.has("ambient")) light.ambient = node.child("ambient").vec3_in(kUnit);  // classic models
    if (node.has("lobes")) read_light_lobes(node.child("lobes"), light);
    return light;
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
        for (std::size_t i = 0; i < count; ++i) scene.lights.push_back(read_light(lights.at(i)));
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

}  // namespace

Scene scene_from_json(const json& doc, const std::string& source, const LoadContext& context) {
    return read_scene(doc, source, {context, ""});
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
    apply_overrides(doc, overrides, source);
    // The files the scene names are relative to its folder.
    return read_scene(doc, source, {context, std::filesystem::path(path).parent_path().string()});
}

}  // namespace m3055
