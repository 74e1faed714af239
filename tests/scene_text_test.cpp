// scene_text: a saved scene's layout. The value never changes (parse gives it
// back for every scene the repository ships), keys come in the spec's order, a
// material's parameters in its model's, and lines stay short.
#include "scene/load.h"
#include "scene/scene_text.h"
#include "test_paths.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace m3055 {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::vector<std::string> shipped_scenes() {
    std::vector<std::string> files;
    for (const char* folder : {"scenes", "assignments/three-point", "assignments/vase-softbox"})
        for (const auto& entry : fs::directory_iterator(test::source_path(folder)))
            if (entry.path().extension() == ".json") files.push_back(entry.path().string());
    return files;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// Where `needle` first occurs in `text` (npos: nowhere).
std::size_t at(const std::string& text, const std::string& needle) { return text.find(needle); }

TEST(SceneText, GivesBackTheSameValueForEveryShippedScene) {
    int scenes = 0;
    for (const std::string& file : shipped_scenes()) {
        json written;
        try {
            written = scene_to_json(load_scene_file(file, LoadContext::trusted()), PathWriting::absolute());
        } catch (const std::exception&) {
            continue;  // an assignment's rules or a class file, not a scene
        }
        const std::string text = scene_text(written);
        EXPECT_EQ(json::parse(text), written) << file;
        ++scenes;
    }
    EXPECT_GE(scenes, 15);
}

TEST(SceneText, KeepsAnyValueIncludingKeysItDoesNotKnow) {
    const json value = json::parse(R"({"zeta": [1, [2, 3], {"b": 1, "a": "x\"y"}], "display": {"width": 4},
        "alpha": {}, "lights": [], "objects": [{"shape": "sphere", "unknown": null, "material": {"model": "nope"}}]})");
    EXPECT_EQ(json::parse(scene_text(value)), value);
}

TEST(SceneText, PutsKeysInTheSpecsOrderAndParametersInTheModelsOrder) {
    const json written = scene_to_json(load_scene_file(test::source_path("scenes/spec_example.json"),
                                                       LoadContext::trusted()),
                                       PathWriting::absolute());
    const std::string text = scene_text(written);
    // The scene's parts, a camera's, a light's, a sphere's.
    EXPECT_LT(at(text, "\"display\""), at(text, "\"background\""));
    EXPECT_LT(at(text, "\"background\""), at(text, "\"camera\""));
    EXPECT_LT(at(text, "\"camera\""), at(text, "\"lights\""));
    EXPECT_LT(at(text, "\"lights\""), at(text, "\"objects\""));
    EXPECT_LT(at(text, "\"width\""), at(text, "\"height\""));
    EXPECT_LT(at(text, "\"projection\""), at(text, "\"position\""));
    EXPECT_LT(at(text, "\"target\""), at(text, "\"fov_y_deg\""));
    EXPECT_LT(at(text, "\"type\""), at(text, "\"direction\""));
    EXPECT_LT(at(text, "\"direction\""), at(text, "\"intensity\""));
    EXPECT_LT(at(text, "\"shape\""), at(text, "\"center\""));
    EXPECT_LT(at(text, "\"radius\""), at(text, "\"material\""));
    // The paper's highlight model: color, d, w, m (the model table's order), on one line.
    EXPECT_NE(at(text, R"("material": { "model": "highlight", "color": [0.8, 0.2, 0.2], "d": 0.5, "w": 1.0, "m": 10.0 })"),
              std::string::npos)
        << text;
    EXPECT_NE(at(text, R"("background": [0.0, 0.0, 0.0],)"), std::string::npos) << text;
    EXPECT_LE(lines_of(text).size(), 30u) << text;  // nlohmann's dump(2) made 70 lines of it
}

TEST(SceneText, KeepsLinesWithinAHundredColumns) {
    json value = {{"lights", json::array()}, {"objects", json::array()}};
    json spectrum = json::array();
    for (int nm = 380; nm <= 780; nm += 5) spectrum.push_back(0.123456789 + nm * 1e-4);
    value["objects"].push_back(
        {{"shape", "sphere"}, {"material", {{"model", "lambert"}, {"color_spectrum", {{"values", spectrum}}}}}});
    for (const std::string& file : shipped_scenes()) {
        try {
            value["objects"].push_back(scene_to_json(load_scene_file(file, LoadContext::trusted()),
                                                     PathWriting::absolute())["objects"][0]);
        } catch (const std::exception&) {
        }
    }
    const std::string text = scene_text(value);
    ASSERT_EQ(json::parse(text), value);
    for (const std::string& line : lines_of(text)) EXPECT_LE(line.size(), 100u) << line;
}

TEST(SceneText, GivesEachLightAndObjectItsOwnLine) {
    const json value = json::parse(R"({"lights": [{"type": "sky"}, {"type": "sky"}], "objects": [{"shape": "sphere"}]})");
    EXPECT_EQ(scene_text(value), "{\n"
                                 "  \"lights\": [\n"
                                 "    { \"type\": \"sky\" },\n"
                                 "    { \"type\": \"sky\" }\n"
                                 "  ],\n"
                                 "  \"objects\": [\n"
                                 "    { \"shape\": \"sphere\" }\n"
                                 "  ]\n"
                                 "}\n");
}

}  // namespace
}  // namespace m3055
