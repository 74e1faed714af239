// Scene loader (docs/spec.md#7-scene-files): exact values, defaults, one-line error messages
// naming file and JSON path, --set overrides, and the scene_to_json round trip.
#include "material_support.h"
#include "test_paths.h"
#include "scene/json_node.h"
#include "scene/load.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <functional>
#include <random>

namespace m3055 {
namespace {

using nlohmann::json;
using test::TempDir;

const char* kSpecExample = R"({
  "display":    { "width": 512, "height": 320, "bits": 5 },
  "background": [0.0, 0.0, 0.0],
  "camera":     { "projection": "perspective", "position": [0, 0, 4.5],
                  "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 30 },
  "lights": [
    { "type": "directional", "direction": [1, 1, 1], "intensity": 1.0, "color": [1, 1, 1] }
  ],
  "objects": [
    { "shape": "sphere", "center": [0, 0, 0], "radius": 1.0,
      "material": { "model": "highlight", "color": [0.8, 0.2, 0.2], "d": 0.5, "w": 1.0, "m": 10 } }
  ]
})";

json spec_doc() { return json::parse(kSpecExample); }

// The message scene_from_json gives for the spec example after `edit`, or "no error".
std::string error_after(const std::function<void(json&)>& edit) {
    json doc = spec_doc();
    edit(doc);
    try {
        scene_from_json(doc, "scene.json", LoadContext::trusted());
    } catch (const SceneError& error) {
        return error.what();
    }
    return "no error";
}

std::string repo_path(const std::string& relative) { return std::string(M3055_SOURCE_DIR) + "/" + relative; }

Scene load_text(const std::string& text) {
    return scene_from_json(json::parse(text), "scene.json", LoadContext::trusted());
}

void expect_vec(const dvec3& got, const dvec3& want) {
    EXPECT_EQ(got.x, want.x);
    EXPECT_EQ(got.y, want.y);
    EXPECT_EQ(got.z, want.z);
}

void expect_lobes(const std::vector<Lobe>& got, const std::vector<Lobe>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        EXPECT_EQ(got[i].w, want[i].w) << "lobe " << i;
        EXPECT_EQ(got[i].m, want[i].m) << "lobe " << i;
    }
}

// Field by field, exact: the round trip must not lose a single bit.
void expect_same_scene(const Scene& a, const Scene& b) {
    EXPECT_EQ(a.display.width, b.display.width);
    EXPECT_EQ(a.display.height, b.display.height);
    EXPECT_EQ(a.display.bits, b.display.bits);
    EXPECT_EQ(a.display.dither, b.display.dither);
    expect_vec(a.background, b.background);
    EXPECT_EQ(a.camera.projection, b.camera.projection);
    expect_vec(a.camera.position, b.camera.position);
    expect_vec(a.camera.target, b.camera.target);
    expect_vec(a.camera.up, b.camera.up);
    EXPECT_EQ(a.camera.fov_y_deg, b.camera.fov_y_deg);
    EXPECT_EQ(a.camera.height, b.camera.height);
    ASSERT_EQ(a.lights.size(), b.lights.size());
    for (std::size_t i = 0; i < a.lights.size(); ++i) {
        SCOPED_TRACE("light " + std::to_string(i));
        const Light &x = a.lights[i], &y = b.lights[i];
        EXPECT_EQ(x.type, y.type);
        expect_vec(x.direction, y.direction);
        expect_vec(x.position, y.position);
        EXPECT_EQ(x.intensity, y.intensity);
        expect_vec(x.color, y.color);
        EXPECT_EQ(x.att_constant, y.att_constant);
        EXPECT_EQ(x.att_linear, y.att_linear);
        EXPECT_EQ(x.att_quadratic, y.att_quadratic);
        expect_vec(x.spot_direction, y.spot_direction);
        EXPECT_EQ(x.spot_exponent, y.spot_exponent);
        expect_lobes(x.lobes, y.lobes);
        EXPECT_EQ(x.lobe_kind, y.lobe_kind);
        EXPECT_EQ(x.enabled, y.enabled);
    }
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (std::size_t i = 0; i < a.objects.size(); ++i) {
        SCOPED_TRACE("object " + std::to_string(i));
        const Object &x = a.objects[i], &y = b.objects[i];
        EXPECT_EQ(x.shape, y.shape);
        expect_vec(x.center, y.center);
        EXPECT_EQ(x.radius, y.radius);
        EXPECT_TRUE(test::same_material(x.material, y.material));  // the model and every parameter
    }
}

// ---- valid scenes -------------------------------------------------------------

TEST(SceneLoader, SpecExampleLoadsWithExactValues) {
    const Scene scene = load_text(kSpecExample);
    EXPECT_EQ(scene.display.width, 512);
    EXPECT_EQ(scene.display.height, 320);
    EXPECT_EQ(scene.display.bits, 5);
    EXPECT_FALSE(scene.display.dither);
    expect_vec(scene.background, {0, 0, 0});
    EXPECT_EQ(scene.camera.projection, Projection::perspective);
    expect_vec(scene.camera.position, {0, 0, 4.5});
    expect_vec(scene.camera.target, {0, 0, 0});
    expect_vec(scene.camera.up, {0, 1, 0});
    EXPECT_EQ(scene.camera.fov_y_deg, 30.0);
    ASSERT_EQ(scene.lights.size(), 1u);
    const Light& light = scene.lights[0];
    EXPECT_EQ(light.type, LightType::directional);
    const double k = 1.0 / std::sqrt(3.0);
    EXPECT_NEAR(light.direction.x, k, 1e-15);
    EXPECT_NEAR(light.direction.y, k, 1e-15);
    EXPECT_NEAR(light.direction.z, k, 1e-15);
    EXPECT_EQ(light.intensity, 1.0);
    expect_vec(light.color, {1, 1, 1});
    EXPECT_TRUE(light.enabled);
    EXPECT_TRUE(light.lobes.empty());
    ASSERT_EQ(scene.objects.size(), 1u);
    const Object& object = scene.objects[0];
    EXPECT_EQ(object.shape, Shape::sphere);
    expect_vec(object.center, {0, 0, 0});
    EXPECT_EQ(object.radius, 1.0);
    EXPECT_EQ(object.material.model_name(), "highlight");
    expect_vec(object.material.vec3("color"), {0.8, 0.2, 0.2});
    EXPECT_EQ(object.material.number("d"), 0.5);
    EXPECT_EQ(object.material.number("w"), 1.0);
    EXPECT_EQ(object.material.number("m"), 10.0);
}

TEST(SceneLoader, ReferenceScenesLoad) {
    const std::string dir = repo_path("tests/data/reference-images");
    const Scene metal = load_scene_file(dir + "/metal_two_lobes.json", LoadContext::trusted());
    EXPECT_EQ(metal.camera.projection, Projection::orthographic);
    EXPECT_EQ(metal.camera.height, 2.5);
    ASSERT_EQ(metal.objects.size(), 1u);
    EXPECT_EQ(metal.objects[0].material.model_name(), "metal");
    expect_lobes(metal.objects[0].material.lobes().to_vector(), {{0.013, 0.2}, {0.1, 0.4}});
    EXPECT_EQ(metal.objects[0].material.number("d"), 0.05);
    ASSERT_EQ(metal.lights.size(), 2u);
    EXPECT_EQ(metal.lights[1].intensity, 0.6);

    const Scene spec = load_scene_file(dir + "/spec_example.json", LoadContext::trusted());
    expect_same_scene(spec, load_text(kSpecExample));

    const Scene layered = load_scene_file(dir + "/translucent_over_opaque.json", LoadContext::trusted());
    ASSERT_GE(layered.objects.size(), 2u);
    bool has_translucent = false;
    for (const Object& object : layered.objects) has_translucent |= object.material.model_name() == "translucent";
    EXPECT_TRUE(has_translucent);
}

TEST(SceneLoader, DefaultsForEverythingOptional) {
    const Scene scene = load_text(R"({
      "camera": { "projection": "orthographic", "position": [0, 0, 5], "target": [0, 0, 0], "height": 3 },
      "lights": [ { "type": "directional", "direction": [0, 0, 2] },
                  { "type": "point", "position": [1, 2, 3] },
                  { "type": "spot", "position": [0, 3, 0], "spot_direction": [0, -5, 0] } ],
      "objects": [
        { "center": [0, 0, 0], "radius": 1, "material": { "model": "highlight", "color": [1, 0, 0] } },
        { "center": [0, 0, 0], "radius": 1, "material": { "model": "translucent", "color": [1, 0, 0] } },
        { "center": [0, 0, 0], "radius": 1, "material": { "model": "metal", "color": [1, 0, 0] } },
        { "center": [0, 0, 0], "radius": 1, "material": { "model": "metal_blinn", "color": [1, 0, 0] } },
        { "center": [0, 0, 0], "radius": 1, "material": { "model": "metal_phong", "color": [1, 0, 0] } } ]
    })");
    EXPECT_EQ(scene.display.width, 512);
    EXPECT_EQ(scene.display.height, 320);
    EXPECT_EQ(scene.display.bits, 5);
    EXPECT_FALSE(scene.display.dither);
    expect_vec(scene.background, {0, 0, 0});
    expect_vec(scene.camera.up, {0, 1, 0});
    EXPECT_EQ(scene.camera.height, 3.0);

    for (const Light& light : scene.lights) {
        EXPECT_EQ(light.intensity, 1.0);
        expect_vec(light.color, {1, 1, 1});
        EXPECT_TRUE(light.enabled);
        EXPECT_EQ(light.att_constant, 1.0);
        EXPECT_EQ(light.att_linear, 0.0);
        EXPECT_EQ(light.att_quadratic, 0.0);
        EXPECT_TRUE(light.lobes.empty());
    }
    expect_vec(scene.lights[0].direction, {0, 0, 1});       // normalized on load
    expect_vec(scene.lights[1].position, {1, 2, 3});
    expect_vec(scene.lights[2].spot_direction, {0, -1, 0});  // normalized on load
    EXPECT_EQ(scene.lights[2].spot_exponent, 1.0);

    const Material& highlight = scene.objects[0].material;
    EXPECT_EQ(highlight.number("d"), 0.5);
    EXPECT_EQ(highlight.number("w"), 1.0);
    EXPECT_EQ(highlight.number("m"), 10.0);
    const Material& translucent = scene.objects[1].material;
    EXPECT_EQ(translucent.number("d"), 0.5);
    EXPECT_EQ(translucent.number("w"), 1.0);
    EXPECT_EQ(translucent.number("m"), 10.0);
    EXPECT_EQ(translucent.number("t_n"), 0.8);
    EXPECT_EQ(translucent.number("t_p"), 1.0);
    EXPECT_EQ(scene.objects[2].material.number("d"), 0.05);
    expect_lobes(scene.objects[2].material.lobes().to_vector(), {{0.013, 0.2}, {0.1, 0.4}});
    // The cheap metals' defaults are the explorer's presets (Figs. 12 and 13),
    // which meet eq. 14 with d = 0.05.
    EXPECT_EQ(scene.objects[3].material.number("d"), 0.05);
    expect_lobes(scene.objects[3].material.lobes().to_vector(), {{0.95, 13.0}});
    EXPECT_EQ(scene.objects[4].material.number("d"), 0.05);
    expect_lobes(scene.objects[4].material.lobes().to_vector(), {{0.19, 20.0}, {0.76, 3.0}});
}

TEST(SceneLoader, IntegralFloatsAreWholeNumbersAndEmptyListsAreFine) {
    json doc = spec_doc();
    doc["display"]["width"] = 640.0;
    doc["display"]["bits"] = 8.0;
    doc["lights"] = json::array();
    doc["objects"] = json::array();
    const Scene scene = scene_from_json(doc, "scene.json", LoadContext::trusted());
    EXPECT_EQ(scene.display.width, 640);
    EXPECT_EQ(scene.display.bits, 8);
    EXPECT_TRUE(scene.lights.empty());
    EXPECT_TRUE(scene.objects.empty());
}

TEST(SceneLoader, LightAttenuationAndLobes) {
    const Scene scene = load_text(R"({
      "camera": { "projection": "perspective", "position": [0, 0, 5], "target": [0, 0, 0], "fov_y_deg": 40 },
      "lights": [ { "type": "point", "position": [1, 2, 3], "attenuation": "inverse" },
                  { "type": "point", "position": [1, 2, 3], "attenuation": "physical" },
                  { "type": "spot", "position": [1, 2, 3], "spot_direction": [0, 0, -1],
                    "attenuation": [0.5, 0.25, 0.125], "spot_exponent": 7 },
                  { "type": "directional", "direction": [3, 0, 4],
                    "lobes": [ { "w": 0.01, "m": 0.4 } ] },
                  { "type": "directional", "direction": [0, 1, 0], "enabled": false,
                    "lobes": [ { "w": 0.5, "n": 8 }, { "w": 0.25, "n": 2 } ] } ],
      "objects": []
    })");
    EXPECT_EQ(scene.lights[0].att_constant, 0.0);
    EXPECT_EQ(scene.lights[0].att_linear, 1.0);
    EXPECT_EQ(scene.lights[0].att_quadratic, 0.0);
    EXPECT_EQ(scene.lights[1].att_constant, 0.0);
    EXPECT_EQ(scene.lights[1].att_linear, 0.0);
    EXPECT_EQ(scene.lights[1].att_quadratic, 1.0);
    EXPECT_EQ(scene.lights[2].att_constant, 0.5);
    EXPECT_EQ(scene.lights[2].att_linear, 0.25);
    EXPECT_EQ(scene.lights[2].att_quadratic, 0.125);
    EXPECT_EQ(scene.lights[2].spot_exponent, 7.0);
    EXPECT_NEAR(scene.lights[3].direction.x, 0.6, 1e-16);
    EXPECT_NEAR(scene.lights[3].direction.z, 0.8, 1e-16);
    EXPECT_EQ(scene.lights[3].lobe_kind, LobeKind::beckmann);
    expect_lobes(scene.lights[3].lobes, {{0.01, 0.4}});
    EXPECT_EQ(scene.lights[4].lobe_kind, LobeKind::exponent);
    expect_lobes(scene.lights[4].lobes, {{0.5, 8}, {0.25, 2}});
    EXPECT_FALSE(scene.lights[4].enabled);
}

// ---- directions -------------------------------------------------------------

TEST(SceneLoader, DirectionsAreUnitEvenForTinyAndHugeInputs) {
    for (double scale : {1e-300, 1e-5, 1.0, 7.0, 1e200, 1e300}) {
        json doc = spec_doc();
        doc["lights"][0]["direction"] = {3 * scale, 0.0, -4 * scale};
        const Scene scene = scene_from_json(doc, "scene.json", LoadContext::trusted());
        const dvec3 d = scene.lights[0].direction;
        EXPECT_NEAR(d.x, 0.6, 1e-15) << scale;
        EXPECT_EQ(d.y, 0.0);
        EXPECT_NEAR(d.z, -0.8, 1e-15) << scale;
    }
}

TEST(SceneLoader, UnitVectorIsIdempotentSoReloadingKeepsDirectionsBitExact) {
    std::mt19937_64 random(3055);
    std::uniform_real_distribution<double> component(-10.0, 10.0);
    for (int i = 0; i < 20000; ++i) {
        const dvec3 v(component(random), component(random), component(random));
        if (v == dvec3(0.0)) continue;
        const dvec3 once = scene_json::unit_vector(v);
        const dvec3 twice = scene_json::unit_vector(once);
        ASSERT_EQ(once, twice) << i;
        ASSERT_NEAR(std::sqrt(once.x * once.x + once.y * once.y + once.z * once.z), 1.0, 4e-16);
    }
}

// ---- one-line errors naming file and path ----------------------------------

struct ErrorCase {
    const char* what;
    std::function<void(json&)> edit;
    std::string message;  // full what()
};

TEST(SceneLoader, EveryErrorClassGivesItsExactOneLineMessage) {
    const std::vector<ErrorCase> cases = {
        {"the spec's own example", [](json& d) { d["objects"][0]["material"]["m"] = -3; },
         "scene.json: objects[0].material.m: must be in [0, 10000], got -3"},
        {"unknown key in material", [](json& d) { d["objects"][0]["material"]["foo"] = 1; },
         "scene.json: objects[0].material.foo: unknown key"},
        {"unknown root key", [](json& d) { d["lamps"] = json::array(); },
         "scene.json: lamps: unknown key"},
        {"root not an object", [](json& d) { d = json::array(); },
         "scene.json: (root): must be an object"},
        {"required camera key", [](json& d) { d["camera"].erase("fov_y_deg"); },
         "scene.json: camera.fov_y_deg: is required"},
        {"required camera", [](json& d) { d.erase("camera"); }, "scene.json: camera: is required"},
        {"required objects", [](json& d) { d.erase("objects"); }, "scene.json: objects: is required"},
        {"whole number", [](json& d) { d["display"]["width"] = 12.5; },
         "scene.json: display.width: must be a whole number, got 12.5"},
        {"display range", [](json& d) { d["display"]["height"] = 8193; },
         "scene.json: display.height: must be in [1, 8192], got 8193"},
        {"bits range", [](json& d) { d["display"]["bits"] = 0; },
         "scene.json: display.bits: must be in [1, 8], got 0"},
        {"dither type", [](json& d) { d["display"]["dither"] = 1; },
         "scene.json: display.dither: must be true or false, got 1"},
        {"vector shape", [](json& d) { d["lights"].push_back({{"type", "directional"}, {"direction", {1, 2}}}); },
         "scene.json: lights[1].direction: must be an array of 3 numbers"},
        {"vector element type", [](json& d) { d["camera"]["position"] = {0, "0", 4}; },
         "scene.json: camera.position: must be an array of 3 numbers"},
        {"colour component range", [](json& d) { d["background"] = {0, 1.5, 0}; },
         "scene.json: background[1]: must be in [0, 1], got 1.5"},
        {"zero direction", [](json& d) { d["lights"][0]["direction"] = {0, 0, 0}; },
         "scene.json: lights[0].direction: must be non-zero"},
        {"projection name", [](json& d) { d["camera"]["projection"] = "fisheye"; },
         "scene.json: camera.projection: must be \"perspective\" or \"orthographic\", got \"fisheye\""},
        {"height on a perspective camera", [](json& d) { d["camera"]["height"] = 2; },
         "scene.json: camera.height: only for orthographic cameras"},
        {"fov on an orthographic camera",
         [](json& d) {
             d["camera"]["projection"] = "orthographic";
             d["camera"]["height"] = 2;
         },
         "scene.json: camera.fov_y_deg: only for perspective cameras"},
        {"fov open interval", [](json& d) { d["camera"]["fov_y_deg"] = 180; },
         "scene.json: camera.fov_y_deg: must be in (0, 180), got 180"},
        {"ortho height > 0",
         [](json& d) {
             d["camera"]["projection"] = "orthographic";
             d["camera"].erase("fov_y_deg");
             d["camera"]["height"] = 0;
         },
         "scene.json: camera.height: must be in (0, 1000000], got 0"},
        {"position equals target", [](json& d) { d["camera"]["target"] = {0, 0, 4.5}; },
         "scene.json: camera.target: must differ from camera.position"},
        {"up parallel", [](json& d) { d["camera"]["up"] = {0, 0, -2}; },
         "scene.json: camera.up: must not be parallel to the view direction"},
        {"default up parallel",
         [](json& d) {
             d["camera"].erase("up");
             d["camera"]["position"] = {0, 5, 0};
         },
         "scene.json: camera.up: must not be parallel to the view direction (default [0, 1, 0])"},
        {"up zero", [](json& d) { d["camera"]["up"] = {0, 0, 0}; }, "scene.json: camera.up: must be non-zero"},
        {"light type", [](json& d) { d["lights"][0]["type"] = "area"; },
         "scene.json: lights[0].type: must be \"directional\", \"point\", \"spot\", \"rect\", \"disk\" or \"sky\", got \"area\""},
        {"attenuation on a directional light", [](json& d) { d["lights"][0]["attenuation"] = "inverse"; },
         "scene.json: lights[0].attenuation: only for point and spot lights"},
        {"direction on a point light",
         [](json& d) { d["lights"][0]["type"] = "point"; },
         "scene.json: lights[0].direction: only for directional lights"},
        {"spot key on a point light",
         [](json& d) {
             d["lights"][0] = {{"type", "point"}, {"position", {0, 0, 0}}, {"spot_exponent", 2}};
         },
         "scene.json: lights[0].spot_exponent: only for spot lights"},
        {"spot needs spot_direction",
         [](json& d) { d["lights"][0] = {{"type", "spot"}, {"position", {0, 0, 0}}}; },
         "scene.json: lights[0].spot_direction: is required"},
        {"attenuation all zero",
         [](json& d) { d["lights"][0] = {{"type", "point"}, {"position", {0, 0, 0}}, {"attenuation", {0, 0, 0}}}; },
         "scene.json: lights[0].attenuation: must not be all zero"},
        {"attenuation negative",
         [](json& d) { d["lights"][0] = {{"type", "point"}, {"position", {0, 0, 0}}, {"attenuation", {1, -1, 0}}}; },
         "scene.json: lights[0].attenuation[1]: must be in [0, 1000000], got -1"},
        {"attenuation name",
         [](json& d) { d["lights"][0] = {{"type", "point"}, {"position", {0, 0, 0}}, {"attenuation", "cubic"}}; },
         "scene.json: lights[0].attenuation: must be \"constant\", \"inverse\" or \"physical\", got \"cubic\""},
        {"intensity range", [](json& d) { d["lights"][0]["intensity"] = 11; },
         "scene.json: lights[0].intensity: must be in [0, 10], got 11"},
        {"light colour", [](json& d) { d["lights"][0]["color"] = {1, 1, -0.25}; },
         "scene.json: lights[0].color[2]: must be in [0, 1], got -0.25"},
        {"too many lights",
         [](json& d) {
             for (int i = 0; i < 16; ++i) d["lights"].push_back(d["lights"][0]);
         },
         "scene.json: lights: must have at most 16 lights, got 17"},
        {"light lobes: both m and n", [](json& d) { d["lights"][0]["lobes"] = {{{"w", 1}, {"m", 0.2}, {"n", 3}}}; },
         "scene.json: lights[0].lobes[0]: must have exactly one of \"m\" and \"n\""},
        {"light lobes: mixed kinds",
         [](json& d) { d["lights"][0]["lobes"] = {{{"w", 1}, {"m", 0.2}}, {{"w", 1}, {"n", 3}}}; },
         "scene.json: lights[0].lobes[1].n: all lobes of a light must use the same key (lobes[0] uses \"m\")"},
        {"light lobes: Beckmann m range", [](json& d) { d["lights"][0]["lobes"] = {{{"w", 1}, {"m", 0}}}; },
         "scene.json: lights[0].lobes[0].m: must be in [0.001, 2], got 0"},
        {"light lobes: empty", [](json& d) { d["lights"][0]["lobes"] = json::array(); },
         "scene.json: lights[0].lobes: must have 1 to 4 lobes, got 0"},
        {"model name", [](json& d) { d["objects"][0]["material"]["model"] = "plastic"; },
         "scene.json: objects[0].material.model: must be \"highlight\", \"translucent\", \"metal\", "
         "\"metal_blinn\", \"metal_phong\", \"lambert\", \"half_lambert\", \"half_lambert_clamped\", "
         "\"half_lambert_normalized\", \"oren_nayar\", \"minnaert\", \"phong\", \"blinn_phong\", \"microfacet\", "
         "\"ward\", \"heidrich_seidel\", \"principled\" or \"brdf\", got \"plastic\""},
        {"key of another model", [](json& d) { d["objects"][0]["material"]["t_n"] = 0.5; },
         "scene.json: objects[0].material.t_n: not a parameter of model highlight"},
        {"lobes on highlight", [](json& d) { d["objects"][0]["material"]["lobes"] = json::array(); },
         "scene.json: objects[0].material.lobes: not a parameter of model highlight"},
        {"w on metal",
         [](json& d) {
             d["objects"][0]["material"]["model"] = "metal";
             d["objects"][0]["material"].erase("m");
         },
         "scene.json: objects[0].material.w: not a parameter of model metal"},
        {"m inside a metal_blinn lobe",
         [](json& d) {
             d["objects"][0]["material"] = {{"model", "metal_blinn"}, {"color", {1, 1, 1}},
                                            {"lobes", {{{"w", 1}, {"m", 0.3}}}}};
         },
         "scene.json: objects[0].material.lobes[0].m: not a parameter of model metal_blinn "
         "(its lobes use \"w\" and \"n\")"},
        {"metal lobe needs m",
         [](json& d) {
             d["objects"][0]["material"] = {{"model", "metal"}, {"color", {1, 1, 1}}, {"lobes", {{{"w", 1}}}}};
         },
         "scene.json: objects[0].material.lobes[0].m: is required"},
        {"empty material lobes",
         [](json& d) {
             d["objects"][0]["material"] = {{"model", "metal"}, {"color", {1, 1, 1}}, {"lobes", json::array()}};
         },
         "scene.json: objects[0].material.lobes: must have 1 to 4 lobes, got 0"},
        {"five lobes",
         [](json& d) {
             d["objects"][0]["material"] = {{"model", "metal_phong"}, {"color", {1, 1, 1}},
                                            {"lobes", json::array({{{"w", 1}, {"n", 2}}, {{"w", 1}, {"n", 2}},
                                                                   {{"w", 1}, {"n", 2}}, {{"w", 1}, {"n", 2}},
                                                                   {{"w", 1}, {"n", 2}}})}};
         },
         "scene.json: objects[0].material.lobes: must have 1 to 4 lobes, got 5"},
        {"lobe weight", [](json& d) {
             d["objects"][0]["material"] = {{"model", "metal"}, {"color", {1, 1, 1}},
                                            {"lobes", {{{"w", 101}, {"m", 0.3}}}}};
         },
         "scene.json: objects[0].material.lobes[0].w: must be in [0, 100], got 101"},
        {"t_p range",
         [](json& d) {
             d["objects"][0]["material"] = {{"model", "translucent"}, {"color", {1, 1, 1}}, {"t_p", 10.5}};
         },
         "scene.json: objects[0].material.t_p: must be in [0, 10], got 10.5"},
        {"d range", [](json& d) { d["objects"][0]["material"]["d"] = 1.0000001; },
         "scene.json: objects[0].material.d: must be in [0, 1], got 1.0000001"},
        {"material colour required", [](json& d) { d["objects"][0]["material"].erase("color"); },
         "scene.json: objects[0].material.color: is required"},
        {"number type", [](json& d) { d["objects"][0]["material"]["w"] = "high"; },
         "scene.json: objects[0].material.w: must be a number, got \"high\""},
        {"radius > 0", [](json& d) { d["objects"][0]["radius"] = 0; },
         "scene.json: objects[0].radius: must be in (0, 1000000], got 0"},
        {"radius upper bound", [](json& d) { d["objects"][0]["radius"] = 2e6; },
         "scene.json: objects[0].radius: must be in (0, 1000000], got 2000000"},
        {"shape", [](json& d) { d["objects"][0]["shape"] = "teapot"; },
         "scene.json: objects[0].shape: must be \"sphere\", \"plane\", \"cube\", \"cylinder\", \"torus\" or \"mesh\", got \"teapot\""},
        {"objects type", [](json& d) { d["objects"] = {{"a", 1}}; }, "scene.json: objects: must be an array"},
        {"object type", [](json& d) { d["objects"].push_back(3); }, "scene.json: objects[1]: must be an object"},
        {"coordinate bound", [](json& d) { d["objects"][0]["center"] = {0, 0, -1e7}; },
         "scene.json: objects[0].center[2]: must be in [-1000000, 1000000], got -10000000"},
        {"odd key is quoted on one line", [](json& d) { d["objects"][0]["material"]["a\nb"] = 1; },
         "scene.json: objects[0].material[\"a\\nb\"]: unknown key"},
    };
    for (const ErrorCase& c : cases) {
        const std::string got = error_after(c.edit);
        EXPECT_EQ(got, c.message) << c.what;
        EXPECT_EQ(got.find('\n'), std::string::npos) << c.what;
    }
}

TEST(SceneLoader, TooManyObjectsIsAnError) {
    json doc = spec_doc();
    doc["objects"] = json::array();
    for (int i = 0; i < 100001; ++i) doc["objects"].push_back(nullptr);  // count is checked first
    try {
        scene_from_json(doc, "big.json", LoadContext::trusted());
        FAIL() << "no error";
    } catch (const SceneError& error) {
        EXPECT_STREQ(error.what(), "big.json: objects: must have at most 100000 objects, got 100001");
    }
}

// ---- files ------------------------------------------------------------------

std::string load_error(const std::string& path, const std::vector<Override>& overrides = {}) {
    try {
        load_scene_file(path, LoadContext::trusted(), overrides);
    } catch (const SceneError& error) {
        return error.what();
    }
    return "no error";
}

TEST(SceneLoader, FileErrorsNameThePathAsGiven) {
    TempDir dir;
    EXPECT_EQ(load_error(dir.file("missing.json")), dir.file("missing.json") + ": cannot read file: No such file or directory");
    EXPECT_EQ(load_error(dir.path()), dir.path() + ": cannot read file: it is a folder, not a regular file");

    test::write_text(dir.file("broken.json"), "{\n  \"camera\": {\n}\n");
    const std::string broken = load_error(dir.file("broken.json"));
    EXPECT_EQ(broken.rfind(dir.file("broken.json") + ": invalid JSON: parse error at line 4, column 1: ", 0), 0u)
        << broken;
    EXPECT_EQ(broken.find('\n'), std::string::npos);

    test::write_text(dir.file("empty.json"), "");
    EXPECT_EQ(load_error(dir.file("empty.json")).rfind(dir.file("empty.json") + ": invalid JSON: ", 0), 0u);
}

TEST(SceneLoader, DuplicateKeysAreErrorsWithTheirPath) {
    TempDir dir;
    const auto error_for = [&](const std::string& text) {
        test::write_text(dir.file("dup.json"), text);
        return load_error(dir.file("dup.json"));
    };
    const std::string prefix = dir.file("dup.json") + ": ";
    EXPECT_EQ(error_for(R"({"camera": {}, "camera": {}})"), prefix + "camera: duplicate key");
    EXPECT_EQ(error_for(R"({"a": [1, [2, {}], {"x": [{"k": 1}, {"k": 2, "k": 3}]}]})"),
              prefix + "a[2].x[1].k: duplicate key");
    // Same key in sibling objects is fine: the scene is valid.
    std::string text = kSpecExample;
    EXPECT_EQ(error_for(text), "no error");
}

TEST(SceneLoader, NumbersBeyondDoubleAreRejectedNotReadAsInfinity) {
    TempDir dir;
    std::string text = kSpecExample;
    text.replace(text.find("\"m\": 10"), 7, "\"m\": 1e400");
    test::write_text(dir.file("huge.json"), text);
    EXPECT_EQ(load_error(dir.file("huge.json")),
              dir.file("huge.json") + ": invalid JSON: number overflow parsing '1e400'");

    // A --set value of 1e400 is a number too, not the string "1e400".
    test::write_text(dir.file("ok.json"), kSpecExample);
    EXPECT_EQ(load_error(dir.file("ok.json"), {parse_override("objects[0].material.m=-1e400")}),
              dir.file("ok.json") +
                  ": --set objects[0].material.m: invalid value: number overflow parsing '-1e400'");

    // Tiny numbers underflow to 0, which is a legal value where 0 is allowed.
    text = kSpecExample;
    text.replace(text.find("\"m\": 10"), 7, "\"m\": 1e-400");
    EXPECT_EQ(load_text(text).objects[0].material.number("m"), 0.0);
}

TEST(SceneLoader, BadSceneFilesGiveTheirExpectedMessage) {
    // tests/data/bad_scenes/NAME.json holds a broken scene, NAME.expected the
    // message after "NAME.json: " (so the CLI tests can reuse these files).
    const std::string dir = repo_path("tests/data/bad_scenes");
    int checked = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".json") continue;
        const std::string path = entry.path().string();
        std::string expected = test::read_text(dir + "/" + entry.path().stem().string() + ".expected");
        while (!expected.empty() && (expected.back() == '\n' || expected.back() == '\r')) expected.pop_back();
        EXPECT_EQ(load_error(path), path + ": " + expected);
        ++checked;
    }
    EXPECT_GE(checked, 8);
}

// ---- overrides ----------------------------------------------------------------

TEST(SceneLoader, ParseOverrideSplitsAtTheFirstEquals) {
    const Override a = parse_override("objects[0].material.m=40");
    EXPECT_EQ(a.path, "objects[0].material.m");
    EXPECT_EQ(a.value, "40");
    const Override b = parse_override("camera.projection=a=b");
    EXPECT_EQ(b.path, "camera.projection");
    EXPECT_EQ(b.value, "a=b");
    EXPECT_EQ(parse_override("display.dither=").value, "");
    for (const std::string bad : {"no-equals", "=5", ""}) {
        try {
            parse_override(bad);
            ADD_FAILURE() << bad;
        } catch (const SceneError& error) {
            // An empty text is shown as "" (text::quote_name), so the message still says what was typed.
            const std::string shown = bad.empty() ? "\"\"" : bad;
            EXPECT_EQ(std::string(error.what()), "--set " + shown + ": expected path=value");
        }
    }
}

Scene with_overrides(const std::vector<std::string>& texts) {
    json doc = spec_doc();
    std::vector<Override> overrides;
    for (const auto& text : texts) overrides.push_back(parse_override(text));
    return scene_from_json(std::move(doc), overrides, "scene.json", LoadContext::trusted());
}

std::string override_error(const std::vector<std::string>& texts) {
    try {
        with_overrides(texts);
    } catch (const SceneError& error) {
        return error.what();
    }
    return "no error";
}

TEST(SceneLoader, OverridesApplyInOrderWithTheirValuesParsedAsJson) {
    const Scene scene = with_overrides({
        "objects[0].material.m=40",
        "objects[0].material.model=translucent",
        "objects[0].material.t_n=0.25",
        "display.dither=true",
        "camera.position=[0, 1, 5]",
        "lights[1]={\"type\": \"point\", \"position\": [2, 2, 2], \"attenuation\": \"inverse\"}",
        "lights[0].color[1]=0.5",
        "objects[0].radius=2",
        "objects[0].radius=3",  // later wins
    });
    EXPECT_EQ(scene.objects[0].material.number("m"), 40.0);
    EXPECT_EQ(scene.objects[0].material.model_name(), "translucent");
    EXPECT_EQ(scene.objects[0].material.number("t_n"), 0.25);
    EXPECT_TRUE(scene.display.dither);
    expect_vec(scene.camera.position, {0, 1, 5});
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.lights[1].type, LightType::point);
    EXPECT_EQ(scene.lights[1].att_linear, 1.0);
    expect_vec(scene.lights[0].color, {1, 0.5, 1});
    EXPECT_EQ(scene.objects[0].radius, 3.0);
}

TEST(SceneLoader, AKeyATypoAwayFromAnAllowedOneIsSuggested) {
    EXPECT_EQ(error_after([](json& d) { d["lights"][0]["intensty"] = 1; }),
              "scene.json: lights[0].intensty: unknown key (did you mean \"intensity\"?)");
    EXPECT_EQ(error_after([](json& d) { d["camera"]["psoition"] = {0, 0, 1}; }),
              "scene.json: camera.psoition: unknown key (did you mean \"position\"?)");
    // A value one typo from a choice, and a --set path's key one typo from the document's.
    EXPECT_EQ(error_after([](json& d) { d["objects"][0]["material"]["model"] = "higlight"; })
                  .rfind("scene.json: objects[0].material.model: got \"higlight\": did you mean \"highlight\"? (must be ", 0),
              0u);
    EXPECT_EQ(override_error({"objects[0].materal.m=3"}),
              "scene.json: --set objects[0].materal.m: no such key \"materal\" (did you mean \"material\"?)");
    // Too far from any key, or as near to two: no guess.
    EXPECT_EQ(error_after([](json& d) { d["lamps"] = 1; }), "scene.json: lamps: unknown key");
    EXPECT_EQ(error_after([](json& d) { d["objects"][0]["material"]["foo"] = 1; }),
              "scene.json: objects[0].material.foo: unknown key");
}

TEST(SceneLoader, OverrideErrors) {
    // A value the loader refuses is blamed on the --set that gave it, in the file's message.
    EXPECT_EQ(override_error({"objects[0].material.m=-3"}),
              "scene.json: --set objects[0].material.m: objects[0].material.m: must be in [0, 10000], got -3");
    EXPECT_EQ(override_error({"objects[0].material.m=lots", "camera.fov_y_deg=40"}),
              "scene.json: --set objects[0].material.m: objects[0].material.m: must be a number, got \"lots\"");
    EXPECT_EQ(override_error({"objects[0].material.foo=1"}),
              "scene.json: --set objects[0].material.foo: objects[0].material.foo: unknown key");
    // A field inside a value set whole; and the last of two that set the same value.
    EXPECT_EQ(override_error({"lights[0]={\"type\": \"sky\", \"intensity\": -1}"}),
              "scene.json: --set lights[0]: lights[0].intensity: must be in [0, 10], got -1");
    EXPECT_EQ(override_error({"objects[0].material.m=3", "objects[0].material.m=-3"}),
              "scene.json: --set objects[0].material.m: objects[0].material.m: must be in [0, 10000], got -3");
    // A field of the file that an override of its object's kind made wrong: noted.
    EXPECT_EQ(override_error({"lights[0].type=sky"}),
              "scene.json: lights[0].direction: only for directional lights (with --set lights[0].type)");
    // A problem in a field no override set is the file's alone ("m" set, "model" wrong).
    const std::vector<Override> m_set = {{"objects[0].material.m", "3"}};
    for (const std::string message : {"scene.json: objects[0].material.model: unknown model \"x\"",
                                      "scene.json: camera.fov_y_deg: must be a number", "other.json: objects[0].material.m: x"})
        EXPECT_EQ(blame_override(SceneError(message), m_set, "scene.json").what(), message);
    EXPECT_EQ(override_error({"a.b.c=1"}), "scene.json: --set a.b.c: no such key \"a\"");
    EXPECT_EQ(override_error({"camera.b.c=1"}), "scene.json: --set camera.b.c: no such key \"b\"");
    EXPECT_EQ(override_error({"objects[3].radius=1"}),
              "scene.json: --set objects[3].radius: index 3 out of range (objects has 1 entry)");
    EXPECT_EQ(override_error({"lights[5]={}"}),
              "scene.json: --set lights[5]: index 5 out of range (lights has 1 entry)");
    EXPECT_EQ(override_error({"camera[0]=1"}), "scene.json: --set camera[0]: camera is not an array");
    EXPECT_EQ(override_error({"camera.fov_y_deg.x=1"}),
              "scene.json: --set camera.fov_y_deg.x: camera.fov_y_deg is not an object");
    for (const std::string bad : {"a..b", "a.", ".a", "a[x]", "a[]", "a[0", "a]", "a[0]b", "[0]x"})
        EXPECT_EQ(override_error({bad + "=1"}),
                  "scene.json: --set " + bad + ": malformed path (expected e.g. objects[0].material.m)")
            << bad;
}

// ---- round trip -------------------------------------------------------------

const char* kRichScene = R"({
  "display": { "width": 333, "height": 77, "bits": 7, "dither": true },
  "background": [0.1, 0.2, 0.30000000000000004],
  "camera": { "projection": "orthographic", "position": [0.1, -2.7, 5.123456789012345],
              "target": [0.3, 0.1, -0.2], "up": [0.1, 1, 0.2], "height": 3.3333333333333335 },
  "lights": [
    { "type": "directional", "direction": [1, 2, 3], "intensity": 0.7, "color": [1, 0.9, 0.8],
      "lobes": [ { "w": 0.013, "m": 0.2 }, { "w": 0.1, "m": 0.4 } ] },
    { "type": "directional", "direction": [-1, 0.5, 0.1], "enabled": false,
      "lobes": [ { "w": 0.2, "n": 20 }, { "w": 0.8, "n": 3 }, { "w": 0.1, "n": 0 }, { "w": 100, "n": 10000 } ] },
    { "type": "point", "position": [2, 3, 4], "attenuation": [0.5, 0.1, 0.01], "intensity": 10 },
    { "type": "point", "position": [-2, 3, 4], "attenuation": "physical", "color": [0, 0, 1],
      "lobes": [ { "w": 0.01, "m": 0.4 } ] },
    { "type": "spot", "position": [0, 5, 0], "spot_direction": [0.1, -1, 0.05], "spot_exponent": 12.5,
      "attenuation": "inverse", "lobes": [ { "w": 0.4, "n": 8 } ] },
    { "type": "spot", "position": [0, -5, 0], "spot_direction": [0, 1, 0], "intensity": 0 }
  ],
  "objects": [
    { "center": [0, 0, 0], "radius": 1, "material": { "model": "highlight", "color": [0.8, 0.2, 0.2], "m": 37.5, "w": 0.6 } },
    { "shape": "sphere", "center": [1.1, 0, 0], "radius": 0.7,
      "material": { "model": "translucent", "color": [0.2, 0.8, 0.2], "d": 0.4, "t_n": 0.6, "t_p": 1.5 } },
    { "center": [-1.1, 0, 0], "radius": 0.3333333333333333,
      "material": { "model": "metal", "color": [0.9, 0.6, 0.4], "d": 0.05,
                    "lobes": [ { "w": 0.013, "m": 0.2 }, { "w": 0.1, "m": 0.4 } ] } },
    { "center": [0, 1.1, 0], "radius": 0.5,
      "material": { "model": "metal_blinn", "color": [0.7, 0.7, 0.7], "lobes": [ { "w": 1, "n": 13 }, { "w": 0.5, "n": 8 } ] } },
    { "center": [0, -1.1, 0], "radius": 0.5,
      "material": { "model": "metal_phong", "color": [0.7, 0.7, 0.1], "d": 0, "lobes": [ { "w": 0.2, "n": 20 } ] } }
  ]
})";

TEST(SceneLoader, SceneToJsonRoundTripsExactlyThroughText) {
    const Scene original = load_text(kRichScene);
    const std::string text = scene_to_json(original, PathWriting::absolute()).dump(2);
    const Scene reloaded = load_text(text);
    expect_same_scene(original, reloaded);
    // And the written document is a fixed point.
    EXPECT_EQ(scene_to_json(reloaded, PathWriting::absolute()).dump(),
              scene_to_json(original, PathWriting::absolute()).dump());
}

TEST(SceneLoader, SceneToJsonRoundTripsAProgrammaticScene) {
    Scene scene;
    scene.camera.projection = Projection::perspective;
    scene.camera.fov_y_deg = 1.0 / 3.0 * 100.0;
    scene.camera.position = {0.1 + 0.2, 1e-7, 4.5};
    scene.camera.up = scene_json::unit_vector({0.3, 1.0, 0.1});
    Light light;
    light.type = LightType::spot;
    light.position = {std::nextafter(1.0, 2.0), -3.0, 2.0};
    light.spot_direction = scene_json::unit_vector({1.0, 2.0, 3.0});
    light.att_constant = 0.0;
    light.att_quadratic = 1e-300;
    light.spot_exponent = 0.1;
    scene.lights.push_back(light);
    Object object;
    object.radius = 1e-300;
    object.material = Material::of("metal");
    object.material.set_number("d", 0.05);
    object.material.set_lobes({{0.1 / 3.0, 0.001}, {100.0, 2.0}});
    scene.objects.push_back(object);
    expect_same_scene(scene, load_text(scene_to_json(scene, PathWriting::absolute()).dump()));
}

// Every leaf of the rich scene replaced by hostile values: the loader must either
// accept (with finite values only) or throw SceneError with one line, nothing else.
void collect_leaf_paths(const json& value, const json::json_pointer& here, std::vector<json::json_pointer>& out) {
    if (value.is_object()) {
        for (const auto& item : value.items()) collect_leaf_paths(item.value(), here / item.key(), out);
    } else if (value.is_array()) {
        for (std::size_t i = 0; i < value.size(); ++i) collect_leaf_paths(value[i], here / i, out);
    }
    out.push_back(here);
}

bool all_finite(const Scene& scene) {
    const auto finite = [](const dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    bool ok = finite(scene.background) && finite(scene.camera.position) && finite(scene.camera.up) &&
              std::isfinite(scene.camera.fov_y_deg) && std::isfinite(scene.camera.height);
    for (const Light& l : scene.lights)
        ok = ok && finite(l.direction) && finite(l.position) && finite(l.spot_direction) && finite(l.color) &&
             std::isfinite(l.intensity + l.att_constant + l.att_linear + l.att_quadratic + l.spot_exponent);
    for (const Object& o : scene.objects) {
        ok = ok && finite(o.center) && std::isfinite(o.radius);
        for (double value : o.material.values()) ok = ok && std::isfinite(value);  // every parameter of its model
    }
    return ok;
}

TEST(SceneLoader, HostileValuesGiveOneLineErrorsOrFiniteScenes) {
    const json rich = json::parse(kRichScene);
    std::vector<json::json_pointer> leaves;
    collect_leaf_paths(rich, json::json_pointer(), leaves);
    const std::vector<json> hostile = {
        nullptr, true, -1, 0, 0.5, 1e-320, 1e308, -1e308, 8193, "x", "sphere", "\n\t\u0001",
        json::array(), json::array({0, 0, 0}), json::array({1e-300, 0, 0}), json::array({1e308, 1e308, 1e308}),
        json::object(), json::parse(R"({"w": 1, "m": 0.2})")};
    int accepted = 0, rejected = 0;
    for (const auto& pointer : leaves) {
        for (const json& value : hostile) {
            json doc = rich;
            if (pointer.empty()) doc = value; else doc[pointer] = value;
            try {
                const Scene scene = scene_from_json(doc, "fuzz.json", LoadContext::trusted());
                EXPECT_TRUE(all_finite(scene)) << pointer.to_string() << " = " << value.dump();
                ++accepted;
            } catch (const SceneError& error) {
                const std::string message = error.what();
                EXPECT_EQ(message.rfind("fuzz.json: ", 0), 0u) << message;
                EXPECT_EQ(message.find('\n'), std::string::npos) << message;
                ++rejected;
            }
        }
    }
    EXPECT_GT(accepted, 0);
    EXPECT_GT(rejected, accepted);
}

TEST(SceneLoader, ScenesShippedInTheRepositoryLoad) {
    const std::string dir = repo_path("scenes");
    if (!std::filesystem::is_directory(dir)) GTEST_SKIP() << "no scenes/ folder";
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".json") continue;
        EXPECT_EQ(load_error(entry.path().string()), "no error") << entry.path();
    }
}

}  // namespace
}  // namespace m3055
