// Lights in scene files (scene/json_lights.h, docs/spec.md#75-area-lights-the-sky-and-shadows):
// rect, disk and sky lights and "shadow" on every type: exact values and
// defaults, one-line errors naming the light and the field, --set, the round
// trip, and that a scene without them is written as it always was.
#include "scene/area_light.h"
#include "scene/load.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>

#include <cmath>
#include <filesystem>
#include <functional>

namespace m3055 {
namespace {

using nlohmann::json;

const char* kScene = R"({
  "camera": { "projection": "perspective", "position": [0, 0, 4.5], "target": [0, 0, 0], "fov_y_deg": 30 },
  "lights": [ { "type": "directional", "direction": [1, 1, 1] } ],
  "objects": [ { "center": [0, 0, 0], "radius": 1,
                 "material": { "model": "highlight", "color": [0.8, 0.2, 0.2] } } ]
})";

// The scene with lights[0] replaced by `light`.
json scene_with(const json& light) {
    json doc = json::parse(kScene);
    doc["lights"][0] = light;
    return doc;
}

Light load_light(const json& light) {
    return scene_from_json(scene_with(light), "scene.json", LoadContext::trusted()).lights.at(0);
}

std::string load_error(const json& doc) {
    try {
        scene_from_json(doc, "scene.json", LoadContext::trusted());
    } catch (const SceneError& error) {
        return error.what();
    }
    return "no error";
}

const json kRect = json::parse(R"({"type": "rect", "position": [0, 3, 1], "normal": [0, -1, 0], "size": [2, 0.5]})");
const json kDisk = json::parse(R"({"type": "disk", "position": [1, 2, 3], "normal": [0, 0, -2], "radius": 0.25})");
const json kSky = json::parse(R"({"type": "sky"})");

json with(json light, const std::string& key, const json& value) {
    light[key] = value;
    return light;
}

json without(json light, const std::string& key) {
    light.erase(key);
    return light;
}

void expect_vec(const dvec3& got, const dvec3& want) {
    EXPECT_EQ(got.x, want.x);
    EXPECT_EQ(got.y, want.y);
    EXPECT_EQ(got.z, want.z);
}

// ---- values and defaults ----------------------------------------------------------

TEST(LightLoader, RectReadsItsFieldsWithDefaults) {
    const Light rect = load_light(with(kRect, "intensity", 2.5));
    EXPECT_EQ(rect.type, LightType::rect);
    expect_vec(rect.position, {0, 3, 1});
    expect_vec(rect.normal, {0, -1, 0});
    EXPECT_EQ(rect.size[0], 2.0);
    EXPECT_EQ(rect.size[1], 0.5);
    EXPECT_EQ(rect.intensity, 2.5);
    expect_vec(rect.color, {1, 1, 1});
    EXPECT_FALSE(rect.shadow);
    // Its normal is -y: the default up is [0, 0, -1], as the spec says.
    expect_vec(rect.up, {0, 0, -1});
}

TEST(LightLoader, RectDefaultUpIsYUnlessTheNormalIsWithinOneDegreeOfY) {
    const auto up_for = [](const dvec3& n) { return load_light(with(kRect, "normal", {n.x, n.y, n.z})).up; };
    expect_vec(up_for({1, 0, 0}), {0, 1, 0});
    expect_vec(up_for({0, 0, 1}), {0, 1, 0});
    const double just_inside = std::tan(0.99 * M_PI / 180.0), just_outside = std::tan(1.01 * M_PI / 180.0);
    expect_vec(up_for({just_inside, 1, 0}), {0, 0, -1});
    expect_vec(up_for({0, -1, just_inside}), {0, 0, -1});
    expect_vec(up_for({just_outside, 1, 0}), {0, 1, 0});
    // A given up is kept (normalized), and only made perpendicular when used.
    expect_vec(load_light(with(kRect, "up", {0, 0, 3})).up, {0, 0, 1});
}

TEST(LightLoader, RectFrameFollowsNormalAndUp) {
    Light rect = load_light(with(with(kRect, "normal", {0, 0, 1}), "up", {0, 2, 1}));
    const RectFrame frame = rect_frame(rect);
    expect_vec(frame.side1, {0, 1, 0});        // up made perpendicular to the normal
    expect_vec(frame.side0, {-1, 0, 0});       // normal x up
    expect_vec(frame.normal, {0, 0, 1});
    rect = load_light(with(kRect, "normal", {1, 2, 3}));
    const RectFrame tilted = rect_frame(rect);
    EXPECT_NEAR(glm::dot(tilted.side0, tilted.side1), 0.0, 1e-15);
    EXPECT_NEAR(glm::dot(tilted.side1, tilted.normal), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(tilted.side0), 1.0, 1e-15);
    EXPECT_GT(glm::dot(tilted.side1, dvec3(0, 1, 0)), 0.0);
    EXPECT_EQ(emitter_area(rect), 1.0);  // 2 x 0.5
}

TEST(LightLoader, DiskAndSkyReadTheirFields) {
    const Light disk = load_light(with(kDisk, "shadow", true));
    EXPECT_EQ(disk.type, LightType::disk);
    expect_vec(disk.position, {1, 2, 3});
    expect_vec(disk.normal, {0, 0, -1});
    EXPECT_EQ(disk.radius, 0.25);
    EXPECT_TRUE(disk.shadow);
    EXPECT_DOUBLE_EQ(emitter_area(disk), M_PI / 16);

    const Light sky = load_light(kSky);
    EXPECT_EQ(sky.type, LightType::sky);
    expect_vec(sky.up, {0, 1, 0});
    EXPECT_EQ(sky.intensity, 1.0);
    expect_vec(load_light(with(kSky, "up", {0, 0, -4})).up, {0, 0, -1});
    // The sky's radiance a c / pi lights an upward white Lambert plane as a unit light from the zenith.
    EXPECT_DOUBLE_EQ(radiance(load_light(with(kSky, "intensity", 2.0))).g, 2.0 / M_PI);
    EXPECT_DOUBLE_EQ(radiance(disk).r, 16.0 / M_PI);  // a c / area
}

TEST(LightLoader, EveryTypeTakesShadowColourSpectraAndLobes) {
    const json lobes = json::parse(R"([{"w": 0.5, "m": 0.2}])");
    for (const json& light :
         {json::parse(R"({"type": "directional", "direction": [0, 1, 0]})"),
          json::parse(R"({"type": "point", "position": [0, 1, 0]})"),
          json::parse(R"({"type": "spot", "position": [0, 1, 0], "spot_direction": [0, -1, 0]})"), kRect, kDisk,
          kSky}) {
        SCOPED_TRACE(light.dump());
        EXPECT_FALSE(load_light(light).shadow);
        EXPECT_TRUE(load_light(with(light, "shadow", true)).shadow);
        EXPECT_GT(load_light(with(light, "temperature_k", 3200)).color.r, 1.0);
        EXPECT_EQ(load_light(with(light, "lobes", lobes)).lobes.size(), 1u);
        EXPECT_EQ(load_light(with(light, "name", "key")).name, "key");
        EXPECT_FALSE(load_light(with(light, "enabled", false)).enabled);
    }
}

// ---- errors -------------------------------------------------------------------------

struct LightError {
    json light;
    std::string message;  // after "scene.json: "
};

TEST(LightLoader, EveryErrorIsOneLineNamingTheLightAndField) {
    const std::vector<LightError> cases = {
        {json::parse(R"({"type": "area"})"),
         "lights[0].type: must be \"directional\", \"point\", \"spot\", \"rect\", \"disk\" or \"sky\", got \"area\""},
        {with(kRect, "size", {0, 1}), "lights[0].size[0]: must be in [1e-06, 1000000], got 0"},
        {with(kRect, "size", {1, -2}), "lights[0].size[1]: must be in [1e-06, 1000000], got -2"},
        {with(kRect, "size", {1}), "lights[0].size: must be an array of 2 numbers [w, h]"},
        {with(kRect, "size", 1), "lights[0].size: must be an array of 2 numbers [w, h]"},
        {without(kRect, "size"), "lights[0].size: is required"},
        {without(kRect, "normal"), "lights[0].normal: is required"},
        {without(kRect, "position"), "lights[0].position: is required"},
        {with(kRect, "normal", {0, 0, 0}), "lights[0].normal: must be non-zero"},
        {with(kRect, "up", {0, -3, 0}), "lights[0].up: must not be parallel to the light's normal"},
        {with(kRect, "up", {0, 0, 0}), "lights[0].up: must be non-zero"},
        {with(kRect, "radius", 1), "lights[0].radius: only for disk lights"},
        {with(kRect, "position", {0, 2e6, 0}), "lights[0].position[1]: must be in [-1000000, 1000000], got 2000000"},
        {with(kDisk, "radius", 0), "lights[0].radius: must be in [1e-06, 1000000], got 0"},
        {with(kDisk, "radius", -1), "lights[0].radius: must be in [1e-06, 1000000], got -1"},
        {with(kDisk, "radius", "wide"), "lights[0].radius: must be a number, got \"wide\""},
        {without(kDisk, "radius"), "lights[0].radius: is required"},
        {with(kDisk, "normal", {0, 0, 0}), "lights[0].normal: must be non-zero"},
        {with(kDisk, "up", {0, 1, 0}), "lights[0].up: only for rect and sky lights"},
        {with(kDisk, "size", {1, 1}), "lights[0].size: only for rect lights"},
        {with(kSky, "up", {0, 0, 0}), "lights[0].up: must be non-zero"},
        {with(kSky, "position", {0, 1, 0}), "lights[0].position: only for point, spot, rect and disk lights"},
        {with(kSky, "normal", {0, 1, 0}), "lights[0].normal: only for rect and disk lights"},
        {with(kSky, "direction", {0, 1, 0}), "lights[0].direction: only for directional lights"},
        {with(kSky, "intensity", 11), "lights[0].intensity: must be in [0, 10], got 11"},
        {with(kRect, "attenuation", "inverse"), "lights[0].attenuation: only for point and spot lights"},
        {with(kDisk, "spot_exponent", 3), "lights[0].spot_exponent: only for spot lights"},
        {with(kRect, "spot_direction", {0, 1, 0}), "lights[0].spot_direction: only for spot lights"},
        {with(kRect, "ambient", {0.1, 0.1, 0.1}), "lights[0].ambient: only for directional, point and spot lights"},
        {with(kSky, "ambient", {0.1, 0.1, 0.1}), "lights[0].ambient: only for directional, point and spot lights"},
        {with(kDisk, "direction", {0, 1, 0}), "lights[0].direction: only for directional lights"},
        {with(kSky, "shadow", 1), "lights[0].shadow: must be true or false, got 1"},
        {with(kRect, "shadow", "yes"), "lights[0].shadow: must be true or false, got \"yes\""},
        {json::parse(R"({"type": "point", "position": [0, 1, 0], "shadow": null})"),
         "lights[0].shadow: must be true or false, got null"},
        {with(with(kDisk, "name", "key"), "color", {2, 0, 0}), "lights[0].color[0]: must be in [0, 1], got 2"},
        {with(with(kSky, "name", "sky"), "illuminant", "D65x"),
         "lights[0].illuminant: got \"D65x\": did you mean \"D65\"? (must be \"A\", \"B\", \"C\", \"D50\", \"D55\", "
         "\"D65\", \"D93\", \"E\", \"F1\", \"F2\", \"F3\", \"F4\", \"F5\", \"F6\", \"F7\", \"F8\", \"F9\", \"F10\", \"F11\" or "
         "\"F12\")"},
    };
    for (const LightError& c : cases) {
        SCOPED_TRACE(c.light.dump());
        const std::string message = load_error(scene_with(c.light));
        EXPECT_EQ(message, "scene.json: " + c.message);
        EXPECT_EQ(message.find('\n'), std::string::npos);
    }
}

TEST(LightLoader, PositionOnADirectionalLightNamesEveryTypeThatHasOne) {
    EXPECT_EQ(load_error(scene_with(json::parse(R"({"type": "directional", "direction": [0, 1, 0], "position": [0, 1, 0]})"))),
              "scene.json: lights[0].position: only for point, spot, rect and disk lights");
}

TEST(LightLoader, BadSceneFilesNameTheirLightAndField) {
    // The files CLI tests reuse (tests/data/bad_scenes/, checked whole by scene_loader_test).
    for (const char* name : {"rect_zero_size", "disk_negative_radius", "sky_with_position", "shadow_not_boolean",
                             "rect_zero_normal", "rect_with_attenuation", "disk_with_ambient"}) {
        const std::string path = test::source_path(std::string("tests/data/bad_scenes/") + name + ".json");
        ASSERT_TRUE(std::filesystem::exists(path)) << path;
        try {
            load_scene_file(path, LoadContext::trusted());
            ADD_FAILURE() << name << " loaded";
        } catch (const SceneError& error) {
            EXPECT_NE(std::string(error.what()).find(": lights["), std::string::npos) << error.what();
        }
    }
}

// ---- --set ----------------------------------------------------------------------------

Scene with_overrides(const std::vector<std::string>& texts) {
    json doc = json::parse(kScene);
    std::vector<Override> overrides;
    for (const std::string& text : texts) overrides.push_back(parse_override(text));
    apply_overrides(doc, overrides, "scene.json");
    return scene_from_json(doc, "scene.json", LoadContext::trusted());
}

TEST(LightLoader, SetReachesEveryNewField) {
    const Scene scene = with_overrides({
        "lights[0].shadow=true",
        R"(lights[1]={"type": "rect", "position": [0, 2, 0], "normal": [0, -1, 0], "size": [1, 1]})",
        "lights[1].size[1]=0.25",
        "lights[1].up=[1, 0, 0]",
        R"(lights[2]={"type": "disk", "position": [0, 2, 0], "normal": [0, -1, 0], "radius": 1})",
        "lights[2].radius=0.5",
        "lights[2].shadow=true",
        R"(lights[3]={"type": "sky"})",
        "lights[3].up=[0, 0, 1]",
        "lights[3].intensity=0.3",
    });
    ASSERT_EQ(scene.lights.size(), 4u);
    EXPECT_TRUE(scene.lights[0].shadow);
    EXPECT_EQ(scene.lights[1].size[1], 0.25);
    expect_vec(scene.lights[1].up, {1, 0, 0});
    EXPECT_EQ(scene.lights[2].radius, 0.5);
    EXPECT_TRUE(scene.lights[2].shadow);
    expect_vec(scene.lights[3].up, {0, 0, 1});
    EXPECT_EQ(scene.lights[3].intensity, 0.3);
}

TEST(LightLoader, SetErrorsAreTheFilesErrors) {
    try {
        with_overrides({R"(lights[1]={"type": "disk", "position": [0, 2, 0], "normal": [0, -1, 0], "radius": 1})",
                        "lights[1].radius=0"});
        ADD_FAILURE() << "radius 0 loaded";
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.what()), "scene.json: lights[1].radius: must be in [1e-06, 1000000], got 0");
    }
    try {
        with_overrides({"lights[0].shadow=maybe"});
        ADD_FAILURE() << "shadow maybe loaded";
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.what()), "scene.json: lights[0].shadow: must be true or false, got \"maybe\"");
    }
}

// ---- writing back ------------------------------------------------------------------------

TEST(LightLoader, RoundTripIsExactForEveryNewField) {
    json doc = json::parse(kScene);
    doc["lights"] = json::array(
        {with(with(kRect, "up", {0.1, 0.2, 1}), "shadow", true), with(kRect, "normal", {1e-3, 1, 0}),
         with(with(kDisk, "temperature_k", 3200), "lobes", json::parse(R"([{"w": 0.5, "n": 20}])")),
         with(with(kSky, "up", {0.3, 1, 0.1}), "shadow", true),
         json::parse(R"({"type": "point", "position": [0, 1, 0], "shadow": true, "ambient": [0.1, 0, 0]})")});
    const Scene original = scene_from_json(doc, "scene.json", LoadContext::trusted());
    const json written = scene_to_json(original, PathWriting::absolute());
    const Scene reloaded = scene_from_json(json::parse(written.dump()), "scene.json", LoadContext::trusted());
    ASSERT_EQ(reloaded.lights.size(), original.lights.size());
    for (std::size_t i = 0; i < original.lights.size(); ++i) {
        SCOPED_TRACE(i);
        const Light &a = original.lights[i], &b = reloaded.lights[i];
        EXPECT_EQ(a.type, b.type);
        expect_vec(a.position, b.position);
        expect_vec(a.normal, b.normal);
        expect_vec(a.up, b.up);
        EXPECT_EQ(a.size[0], b.size[0]);
        EXPECT_EQ(a.size[1], b.size[1]);
        EXPECT_EQ(a.radius, b.radius);
        EXPECT_EQ(a.shadow, b.shadow);
        EXPECT_EQ(a.temperature_k, b.temperature_k);
        expect_vec(a.color, b.color);
        expect_vec(a.ambient, b.ambient);
        EXPECT_EQ(a.lobes.size(), b.lobes.size());
    }
    // The written document is a fixed point.
    EXPECT_EQ(scene_to_json(reloaded, PathWriting::absolute()).dump(), written.dump());
}

TEST(LightLoader, EachTypeWritesOnlyTheKeysItReads) {
    const auto keys = [](const json& light) {
        std::vector<std::string> out;
        for (const auto& item : light.items()) out.push_back(item.key());
        return out;
    };
    const auto written = [](const json& light) {
        return scene_to_json(scene_from_json(scene_with(light), "scene.json", LoadContext::trusted()),
                             PathWriting::absolute())["lights"][0];
    };
    using Keys = std::vector<std::string>;
    EXPECT_EQ(keys(written(kRect)), (Keys{"color", "enabled", "intensity", "normal", "position", "size", "type", "up"}));
    EXPECT_EQ(keys(written(kDisk)), (Keys{"color", "enabled", "intensity", "normal", "position", "radius", "type"}));
    EXPECT_EQ(keys(written(kSky)), (Keys{"color", "enabled", "intensity", "type", "up"}));
    EXPECT_EQ(written(with(kSky, "shadow", true))["shadow"], true);
    EXPECT_FALSE(written(with(kSky, "shadow", false)).contains("shadow"));
}

TEST(LightLoader, ScenesOfTheRepositoryAreWrittenWithoutShadow) {
    // Every light of the repository's scenes that is not an area light and casts no
    // shadow is written exactly as before area lights existed: no "shadow", no new key.
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::source_path("scenes"))) {
        if (entry.path().extension() != ".json") continue;
        const Scene scene = load_scene_file(entry.path().string(), LoadContext::trusted());
        const json written = scene_to_json(scene, PathWriting::absolute());
        for (std::size_t i = 0; i < scene.lights.size(); ++i) {
            if (is_area_light(scene.lights[i].type) || scene.lights[i].shadow) continue;
            const json& light = written["lights"][i];
            for (const char* key : {"shadow", "normal", "size", "radius"})
                EXPECT_FALSE(light.contains(key)) << entry.path() << ": " << key;
            if (light["type"] != "sky" && light["type"] != "rect") {
                EXPECT_FALSE(light.contains("up")) << entry.path();
            }
        }
        ++scenes;
    }
    EXPECT_GE(scenes, 10);
}

}  // namespace
}  // namespace m3055
