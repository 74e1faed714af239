// scene/load_context.h: what each ready-made context allows. A class's
// scenes (batch, grade) run a .brdf file's code only when the teacher allows
// it; the user's own files always may.
#include "scene/json_brdf.h"
#include "scene/load.h"
#include "scene/load_context.h"
#include "scene/presets.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace m3055 {
namespace {

// The spec's example with its first object's material from a .brdf file.
nlohmann::json scene_with_brdf() {
    nlohmann::json doc = scene_to_json(default_scene(), PathWriting::absolute());
    doc["objects"][0]["material"] = {{"model", "brdf"}, {"file", test::source_path("tests/data/brdf/lambert.brdf")}};
    return doc;
}

std::string load_error(const nlohmann::json& doc, const LoadContext& context) {
    try {
        scene_from_json(doc, "scene.json", context);
        return "";
    } catch (const SceneError& e) {
        return e.what();
    }
}

TEST(LoadContext, AClassRunsCodeOnlyWhenAllowed) {
    EXPECT_EQ(load_error(scene_with_brdf(), LoadContext::for_class(false)),
              "scene.json: objects[0].material.file: " + scene_json::brdf_not_allowed_reason());
    EXPECT_EQ(load_error(scene_with_brdf(), LoadContext::for_class(true)), "");
    EXPECT_EQ(load_error(scene_to_json(default_scene(), PathWriting::absolute()), LoadContext::for_class(false)), "")
        << "a scene without a .brdf material is no code";
}

TEST(LoadContext, TheUsersOwnFilesRunCodeUnconfined) {
    const LoadContext trusted = LoadContext::trusted();
    EXPECT_TRUE(trusted.folder.empty());
    EXPECT_TRUE(trusted.code_refused.empty());
    EXPECT_FALSE(trusted.confinement.has_value());
    EXPECT_EQ(load_error(scene_with_brdf(), trusted), "");
}

}  // namespace
}  // namespace m3055
