// The shapes' fields in scene files (docs/shapes.md): exact values and
// defaults, one-line "FILE: json.path: problem" errors for every new field,
// the triangle budget, and the scene_to_json round trip.
#include "geometry/mesh.h"
#include "scene/load.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <functional>

namespace m3055 {
namespace {

using nlohmann::json;

json base_doc() {
    return json::parse(R"({
      "camera": {"projection": "perspective", "position": [0, 2, 6], "target": [0, 0, 0], "fov_y_deg": 30},
      "objects": [
        {"shape": "plane", "center": [0, -1, 0], "normal": [0, 2, 0], "size": 10,
         "material": {"model": "highlight", "color": [0.5, 0.5, 0.5]}},
        {"shape": "cube", "center": [1, 0, 0], "size": 1.5, "rotation_deg": [10, 20, -30],
         "material": {"model": "highlight", "color": [0.2, 0.2, 0.8]}},
        {"shape": "cylinder", "center": [-1, 0, 0], "axis": [1, 0, 0], "radius": 0.5, "height": 2,
         "capped": false, "segments": 32, "material": {"model": "lambert", "kd": [0.8, 0.8, 0.2]}},
        {"shape": "torus", "center": [0, 1, 0], "axis": [0, 0, 3], "major_radius": 1, "minor_radius": 0.2,
         "segments": 48, "material": {"model": "metal", "color": [0.9, 0.6, 0.4]}}
      ]})");
}

Scene load(const json& doc) { return scene_from_json(doc, "scene.json", LoadContext::trusted()); }

std::string error_after(const std::function<void(json&)>& edit) {
    json doc = base_doc();
    edit(doc);
    try {
        load(doc);
    } catch (const SceneError& error) {
        return error.what();
    }
    return "no error";
}

TEST(ShapesLoader, ReadsEveryFieldExactly) {
    const Scene scene = load(base_doc());
    ASSERT_EQ(scene.objects.size(), 4u);
    const Object& plane = scene.objects[0];
    EXPECT_EQ(plane.shape, Shape::plane);
    EXPECT_EQ(plane.axis, dvec3(0, 1, 0));  // normalized on load
    EXPECT_EQ(plane.size, 10.0);
    const Object& cube = scene.objects[1];
    EXPECT_EQ(cube.shape, Shape::cube);
    EXPECT_EQ(cube.size, 1.5);
    EXPECT_EQ(cube.rotation_deg, dvec3(10, 20, -30));
    const Object& cylinder = scene.objects[2];
    EXPECT_EQ(cylinder.shape, Shape::cylinder);
    EXPECT_EQ(cylinder.axis, dvec3(1, 0, 0));
    EXPECT_EQ(cylinder.radius, 0.5);
    EXPECT_EQ(cylinder.height, 2.0);
    EXPECT_FALSE(cylinder.capped);
    EXPECT_EQ(cylinder.segments, 32);
    const Object& torus = scene.objects[3];
    EXPECT_EQ(torus.shape, Shape::torus);
    EXPECT_EQ(torus.axis, dvec3(0, 0, 1));
    EXPECT_EQ(torus.major_radius, 1.0);
    EXPECT_EQ(torus.minor_radius, 0.2);
    EXPECT_EQ(torus.segments, 48);
    EXPECT_EQ(torus.material.model_name(), "metal");
}

TEST(ShapesLoader, DefaultsForOptionalFields) {
    json doc = base_doc();
    doc["objects"][0].erase("normal");
    doc["objects"][1].erase("rotation_deg");
    doc["objects"][2].erase("axis");
    doc["objects"][2].erase("capped");
    doc["objects"][2].erase("segments");
    doc["objects"][3].erase("axis");
    doc["objects"][3].erase("segments");
    const Scene scene = load(doc);
    EXPECT_EQ(scene.objects[0].axis, dvec3(0, 1, 0));
    EXPECT_EQ(scene.objects[1].rotation_deg, dvec3(0, 0, 0));
    EXPECT_EQ(scene.objects[2].axis, dvec3(0, 1, 0));
    EXPECT_TRUE(scene.objects[2].capped);
    EXPECT_EQ(scene.objects[2].segments, 0);  // 0 = kDefaultSegments
    EXPECT_EQ(segments_of(scene.objects[2]), kDefaultSegments);
    EXPECT_EQ(scene.objects[3].axis, dvec3(0, 1, 0));
}

TEST(ShapesLoader, EveryNewFieldGivesItsOneLineError) {
    struct Case {
        std::function<void(json&)> edit;
        std::string message;
    };
    const std::vector<Case> cases = {
        {[](json& d) { d["objects"][0]["shape"] = "teapot"; },
         R"(scene.json: objects[0].shape: must be "sphere", "plane", "cube", "cylinder", "torus" or "mesh", got "teapot")"},
        {[](json& d) { d["objects"][0]["normal"] = {0, 0, 0}; }, "scene.json: objects[0].normal: must be non-zero"},
        {[](json& d) { d["objects"][0]["normal"] = {0, 1}; },
         "scene.json: objects[0].normal: must be an array of 3 numbers"},
        {[](json& d) { d["objects"][0]["size"] = 0; }, "scene.json: objects[0].size: must be in (0, 1000000], got 0"},
        {[](json& d) { d["objects"][0].erase("size"); }, "scene.json: objects[0].size: is required"},
        {[](json& d) { d["objects"][0]["radius"] = 1; },
         "scene.json: objects[0].radius: only for spheres and cylinders"},
        {[](json& d) { d["objects"][0]["segments"] = 8; },
         "scene.json: objects[0].segments: only for cylinders and tori"},
        {[](json& d) { d["objects"][1]["size"] = -1; },
         "scene.json: objects[1].size: must be in (0, 1000000], got -1"},
        {[](json& d) { d["objects"][1]["rotation_deg"] = {0, 400, 0}; },
         "scene.json: objects[1].rotation_deg[1]: must be in [-360, 360], got 400"},
        {[](json& d) { d["objects"][1]["normal"] = {0, 1, 0}; }, "scene.json: objects[1].normal: only for planes"},
        {[](json& d) { d["objects"][1]["axis"] = {0, 1, 0}; },
         "scene.json: objects[1].axis: only for cylinders and tori"},
        {[](json& d) { d["objects"][2]["axis"] = {0, 0, 0}; }, "scene.json: objects[2].axis: must be non-zero"},
        {[](json& d) { d["objects"][2]["radius"] = 0; },
         "scene.json: objects[2].radius: must be in (0, 1000000], got 0"},
        {[](json& d) { d["objects"][2].erase("height"); }, "scene.json: objects[2].height: is required"},
        {[](json& d) { d["objects"][2]["height"] = 2e6; },
         "scene.json: objects[2].height: must be in (0, 1000000], got 2000000"},
        {[](json& d) { d["objects"][2]["capped"] = 1; }, "scene.json: objects[2].capped: must be true or false, got 1"},
        {[](json& d) { d["objects"][2]["segments"] = 2; },
         "scene.json: objects[2].segments: must be in [3, 512], got 2"},
        {[](json& d) { d["objects"][2]["segments"] = 16.5; },
         "scene.json: objects[2].segments: must be a whole number, got 16.5"},
        {[](json& d) { d["objects"][2]["rotation_deg"] = {0, 0, 0}; },
         "scene.json: objects[2].rotation_deg: only for cubes and meshes"},
        {[](json& d) { d["objects"][3].erase("major_radius"); },
         "scene.json: objects[3].major_radius: is required"},
        {[](json& d) { d["objects"][3]["minor_radius"] = 1; },
         "scene.json: objects[3].minor_radius: must be less than major_radius (1), got 1"},
        {[](json& d) { d["objects"][3]["minor_radius"] = -0.1; },
         "scene.json: objects[3].minor_radius: must be in (0, 1000000], got -0.1"},
        {[](json& d) { d["objects"][3]["segments"] = 513; },
         "scene.json: objects[3].segments: must be in [3, 512], got 513"},
        {[](json& d) { d["objects"][3]["height"] = 1; }, "scene.json: objects[3].height: only for cylinders"},
        {[](json& d) { d["objects"][3]["spin"] = 1; }, "scene.json: objects[3].spin: unknown key"},
    };
    for (const Case& c : cases) {
        const std::string got = error_after(c.edit);
        EXPECT_EQ(got, c.message);
        EXPECT_EQ(got.find('\n'), std::string::npos);
    }
}

TEST(ShapesLoader, TheScenesMeshesHaveATriangleBudget) {
    json doc = base_doc();
    json torus = doc["objects"][3];
    torus["segments"] = 512;  // 524288 triangles each
    doc["objects"] = json::array();
    for (int i = 0; i < 8; ++i) doc["objects"].push_back(torus);  // 4194304 > 4000000
    try {
        load(doc);
        FAIL() << "no error";
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "scene.json: objects[7]: the scene's meshes would have more than 4000000 triangles "
                  "(fewer segments?)");
    }
    doc["objects"].erase(7);
    EXPECT_NO_THROW(load(doc));
}

TEST(ShapesLoader, SceneToJsonRoundTripsEveryShape) {
    const Scene original = load(base_doc());
    const json written = scene_to_json(original, PathWriting::absolute());
    const Scene reloaded = load(json::parse(written.dump()));
    ASSERT_EQ(reloaded.objects.size(), original.objects.size());
    for (std::size_t i = 0; i < original.objects.size(); ++i) {
        const Object &a = original.objects[i], &b = reloaded.objects[i];
        EXPECT_EQ(a.shape, b.shape);
        EXPECT_EQ(a.center, b.center);
        EXPECT_EQ(a.axis, b.axis);
        EXPECT_EQ(a.size, b.size);
        EXPECT_EQ(a.rotation_deg, b.rotation_deg);
        EXPECT_EQ(a.height, b.height);
        EXPECT_EQ(a.capped, b.capped);
        EXPECT_EQ(a.major_radius, b.major_radius);
        EXPECT_EQ(a.minor_radius, b.minor_radius);
        EXPECT_EQ(a.segments, b.segments);
        EXPECT_EQ(a.material.model_name(), b.material.model_name());
        if (a.shape == Shape::cylinder) {
            EXPECT_EQ(a.radius, b.radius);
        }
    }
    EXPECT_EQ(scene_to_json(reloaded, PathWriting::absolute()).dump(), written.dump());  // a fixed point
    EXPECT_EQ(written["objects"][1]["shape"], "cube");
    EXPECT_FALSE(written["objects"][0].contains("segments"));
}

}  // namespace
}  // namespace m3055
