// The explorer's files (explore/files.h), without a window: a saved scene
// loads back equal, a bad file keeps the current scene and says why, a load
// is one undo step, and screenshots never overwrite.
#include "explore_started.h"
#include "explore/brdf_files.h"
#include "explore/files.h"
#include "test_paths.h"
#include "test_support.h"
#include "explore/operations.h"
#include "explore/start.h"
#include "explore/undo.h"
#include "scene/load.h"
#include "scene/presets.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace m3055::explore {
namespace {

namespace fs = std::filesystem;

using test::started;

// A folder of its own under the test's temporary directory, empty.
fs::path fresh_folder(const std::string& name) {
    const fs::path dir = fs::path(::testing::TempDir()) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

TEST(ExploreFiles, SavedSceneLoadsBackEqual) {
    const fs::path dir = fresh_folder("explore_files_round_trip");
    ExplorerState state = started();
    ASSERT_TRUE(load_figure(state, "fig11"));
    set_model(state, "metal_blinn");
    add_object(state, Shape::torus);
    apply_light_preset(state, LightPreset::three_point_cool);
    const std::string file = (dir / "mine.json").string();
    ASSERT_TRUE(save_scene(state, file)) << state.error;
    EXPECT_EQ(state.scene_file, file);
    EXPECT_EQ(state.scene_name, "mine.json");

    ExplorerState other = started();
    ASSERT_TRUE(load_scene(other, file)) << other.error;
    EXPECT_EQ(scene_to_json(other.scene, PathWriting::absolute()), scene_to_json(state.scene, PathWriting::absolute()));
    EXPECT_FALSE(unsaved(other));
    EXPECT_EQ(other.status, "loaded " + file);
}

TEST(ExploreFiles, EveryFigurePresetLoadsAndRoundTrips) {
    const fs::path dir = fresh_folder("explore_files_figures");
    for (const char* name : {"fig05", "fig06", "fig07", "fig08", "fig09", "fig10", "fig11", "fig12", "fig13",
                             "spec_example"}) {
        ExplorerState state = started();
        ASSERT_TRUE(load_figure(state, name)) << name << ": " << state.error;
        const std::string file = (dir / (std::string(name) + ".json")).string();
        ASSERT_TRUE(save_scene(state, file)) << state.error;
        EXPECT_EQ(scene_to_json(load_scene_file(file, LoadContext::trusted()), PathWriting::absolute()),
                  scene_to_json(state.scene, PathWriting::absolute()))
            << name;
    }
    ExplorerState state = started();
    EXPECT_FALSE(load_figure(state, "fig99"));
    EXPECT_EQ(state.error, "no figure preset named 'fig99'");
}

TEST(ExploreFiles, ABadFileKeepsTheSceneAndSaysWhy) {
    ExplorerState state = started();
    const nlohmann::json before = scene_to_json(state.scene, PathWriting::absolute());
    const std::string bad = std::string(M3055_SOURCE_DIR) + "/tests/data/bad_scenes/material_m_negative.json";
    EXPECT_FALSE(load_scene(state, bad));
    EXPECT_EQ(scene_to_json(state.scene, PathWriting::absolute()), before);
    EXPECT_NE(state.load_error.find("objects[0].material.m"), std::string::npos) << state.load_error;
    EXPECT_EQ(state.error, state.load_error);
    EXPECT_FALSE(commit_edits(state)) << "a failed load is no step";
}

TEST(ExploreFiles, ALoadIsOneUndoStepBackToThePreviousScene) {
    const fs::path dir = fresh_folder("explore_files_load_step");
    ExplorerState state = started();
    ASSERT_TRUE(load_figure(state, "fig07"));
    const std::string file = (dir / "seven.json").string();
    ASSERT_TRUE(save_scene(state, file));
    ASSERT_TRUE(load_figure(state, "fig05"));
    commit_edits(state);
    const nlohmann::json fig05 = scene_to_json(state.scene, PathWriting::absolute());
    ASSERT_TRUE(load_scene(state, file));
    commit_edits(state);
    EXPECT_EQ(state.history.undo_label(), "load " + file);
    ASSERT_TRUE(undo(state));
    EXPECT_EQ(scene_to_json(state.scene, PathWriting::absolute()), fig05);
    EXPECT_EQ(state.scene_name, "scenes/fig05.json");
}

TEST(ExploreFiles, ScreenshotPathIsTheNextFreeNumberNamedAfterTheSceneFile) {
    const fs::path dir = fresh_folder("explore_files_screenshots");
    ExplorerState state = started();
    state.screenshot_dir = dir.string();
    EXPECT_EQ(next_screenshot_path(state), (dir / "m3055-0001.png").string());
    std::ofstream(dir / "m3055-0001.png") << "x";
    std::ofstream(dir / "m3055-0002.json") << "x";  // its PNG missing: still taken
    EXPECT_EQ(next_screenshot_path(state), (dir / "m3055-0003.png").string());
    ASSERT_TRUE(save_scene(state, (dir / "lesson.json").string()));
    EXPECT_EQ(next_screenshot_path(state), (dir / "lesson-0001.png").string());
}

TEST(ExploreFiles, StartsFromTheNamedSceneFileAsSavedOrTheSpecExample) {
    const fs::path dir = fresh_folder("explore_files_start");
    ExplorerState plain;
    EXPECT_FALSE(start_scene(plain, "", ""));
    EXPECT_EQ(plain.scene_name, "spec example");
    EXPECT_EQ(scene_to_json(plain.scene, PathWriting::absolute()),
              scene_to_json(default_scene(), PathWriting::absolute()));
    EXPECT_FALSE(unsaved(plain));
    EXPECT_FALSE(plain.history.can_undo());

    ExplorerState saved = started();
    ASSERT_TRUE(load_figure(saved, "fig09"));
    const std::string file = (dir / "nine.json").string();
    ASSERT_TRUE(save_scene(saved, file));
    ExplorerState named;
    EXPECT_FALSE(start_scene(named, file, ""));
    EXPECT_EQ(named.scene_file, file);
    EXPECT_EQ(named.scene_name, file);
    EXPECT_EQ(scene_to_json(named.scene, PathWriting::absolute()), scene_to_json(saved.scene, PathWriting::absolute()));
    EXPECT_FALSE(unsaved(named));

    ExplorerState missing;
    EXPECT_THROW(start_scene(missing, (dir / "none.json").string(), ""), std::exception)
        << "without an assignment, a scene file must exist";
}

TEST(ExploreFiles, SaveIntoAMissingFolderFailsAndKeepsTheScenesFile) {
    ExplorerState state = started();
    EXPECT_FALSE(save_scene(state, (fs::path(::testing::TempDir()) / "no_such_folder" / "x.json").string()));
    EXPECT_FALSE(state.error.empty());
    EXPECT_EQ(state.scene_file, "");
}

// Save As proposes the scene's own file, or (a figure
// preset loaded since) the preset's name in the folder of the last file, never
// m3055-scene.json in the working folder.
TEST(ExploreFiles, SaveAsProposesTheScenesOwnNameAndFolder) {
    const fs::path dir = fresh_folder("explore_files_save_as");
    ExplorerState state = started();
    const std::string file = (dir / "mine.json").string();
    ASSERT_TRUE(save_scene(state, file)) << state.error;
    ASSERT_TRUE(load_scene(state, file)) << state.error;
    request_save_as(state);
    EXPECT_EQ(state.save_path, file);
    ASSERT_TRUE(load_figure(state, "fig10"));
    request_save_as(state);
    EXPECT_EQ(state.save_path, (dir / "fig10.json").string()) << "the preset's name, the last file's folder";
}

// The page saves a scene naming its .brdf file as the user named it
// (relative to the page's work folder, where the picked files are), so the
// downloaded JSON renders next to the downloaded .brdf; the desktop keeps the
// absolute path; a .brdf outside the folder stays absolute in the page too.
TEST(ExploreFiles, ThePageSavesABrdfFileByTheNameTheUserGave) {
    const fs::path dir = fresh_folder("explore_files_brdf_relative");
    fs::create_directories(dir / "work" / "mine");
    fs::copy_file(m3055::test::source_path("tests/data/brdf/lambert.brdf"), dir / "work" / "mine" / "lambert.brdf");
    fs::copy_file(m3055::test::source_path("tests/data/brdf/lambert.brdf"), dir / "elsewhere.brdf");
    auto saved_file_field = [&](ExplorerState& state, const std::string& name, std::size_t object) {
        const fs::path path = dir / "work" / name;
        EXPECT_TRUE(save_scene(state, path.string())) << state.error;
        std::ifstream in(path);
        return nlohmann::json::parse(in)["objects"][object]["material"]["file"].get<std::string>();
    };
    ExplorerState state = started();
    ASSERT_TRUE(open_brdf(state, (dir / "work" / "mine" / "lambert.brdf").string())) << state.brdf_error;
    EXPECT_EQ(saved_file_field(state, "desktop.json", 0), (dir / "work" / "mine" / "lambert.brdf").string());
    state.platform.brdf_paths_relative_to = (dir / "work").string();
    EXPECT_EQ(saved_file_field(state, "page.json", 0), "mine/lambert.brdf");
    ExplorerState loaded = started();
    loaded.platform.brdf_paths_relative_to = state.platform.brdf_paths_relative_to;
    ASSERT_TRUE(load_scene(loaded, (dir / "work" / "page.json").string())) << loaded.load_error;
    EXPECT_EQ(saved_file_field(loaded, "again.json", 0), "mine/lambert.brdf") << "loads back from the saved name";
    ASSERT_TRUE(open_brdf(state, (dir / "elsewhere.brdf").string())) << state.brdf_error;
    EXPECT_EQ(saved_file_field(state, "outside.json", 0), (dir / "elsewhere.brdf").string());
}

}  // namespace
}  // namespace m3055::explore
