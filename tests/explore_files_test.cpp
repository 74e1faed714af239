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

using test::run;
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
    Explorer explorer = started();
    ASSERT_TRUE(run(explorer, command::LoadFigure{"fig11"}));
    run(explorer, command::SetMaterial{explorer.view.selected_object, with_model_named(*selected_material(explorer), "metal_blinn"), ""});
    run(explorer, command::AddObject{Shape::torus});
    run(explorer, command::ApplyLightPreset{LightPreset::three_point_cool});
    const std::string file = (dir / "mine.json").string();
    ASSERT_TRUE(run(explorer, command::SaveTo{file})) << explorer.session.messages.error;
    EXPECT_EQ(explorer.doc.file, file);
    EXPECT_EQ(explorer.doc.name, "mine.json");

    Explorer other = started();
    ASSERT_TRUE(run(other, command::LoadScene{file})) << other.session.messages.error;
    EXPECT_EQ(scene_to_json(other.doc.scene, PathWriting::absolute()), scene_to_json(explorer.doc.scene, PathWriting::absolute()));
    EXPECT_FALSE(unsaved(other.doc));
    EXPECT_EQ(other.session.messages.status, "loaded " + file);
}

TEST(ExploreFiles, EveryFigurePresetLoadsAndRoundTrips) {
    const fs::path dir = fresh_folder("explore_files_figures");
    for (const char* name : {"fig05", "fig06", "fig07", "fig08", "fig09", "fig10", "fig11", "fig12", "fig13",
                             "spec_example"}) {
        Explorer explorer = started();
        ASSERT_TRUE(run(explorer, command::LoadFigure{name})) << name << ": " << explorer.session.messages.error;
        const std::string file = (dir / (std::string(name) + ".json")).string();
        ASSERT_TRUE(run(explorer, command::SaveTo{file})) << explorer.session.messages.error;
        EXPECT_EQ(scene_to_json(load_scene_file(file, LoadContext::trusted()), PathWriting::absolute()), scene_to_json(explorer.doc.scene, PathWriting::absolute())) << name;
    }
    Explorer explorer = started();
    EXPECT_FALSE(run(explorer, command::LoadFigure{"fig99"}));
    EXPECT_EQ(explorer.session.messages.error, "no figure preset named 'fig99'");
}

TEST(ExploreFiles, ABadFileKeepsTheSceneAndSaysWhy) {
    Explorer explorer = started();
    const nlohmann::json before = scene_to_json(explorer.doc.scene, PathWriting::absolute());
    const std::string bad = std::string(M3055_SOURCE_DIR) + "/tests/data/bad_scenes/material_m_negative.json";
    EXPECT_FALSE(run(explorer, command::LoadScene{bad}));
    EXPECT_EQ(scene_to_json(explorer.doc.scene, PathWriting::absolute()), before);
    EXPECT_NE(explorer.session.messages.load_error.find("objects[0].material.m"), std::string::npos) << explorer.session.messages.load_error;
    EXPECT_EQ(explorer.session.messages.error, explorer.session.messages.load_error);
    EXPECT_FALSE(commit_edits(explorer)) << "a failed load is no step";
}

TEST(ExploreFiles, AnAreaLightSceneLoadsWithItsLights) {
    const fs::path dir = fresh_folder("explore_files_area_light");
    nlohmann::json doc = scene_to_json(started().doc.scene, PathWriting::absolute());
    doc["lights"].push_back(
        {{"type", "disk"}, {"position", {0, 3, 0}}, {"normal", {0, -1, 0}}, {"radius", 0.5}, {"shadow", true}});
    const std::string file = (dir / "disk.json").string();
    {
        std::ofstream out(file);
        out << doc.dump();
    }
    Explorer explorer = started();
    ASSERT_TRUE(run(explorer, command::LoadScene{file})) << explorer.session.messages.load_error;
    ASSERT_EQ(explorer.doc.scene.lights.size(), doc["lights"].size());
    const Light& disk = explorer.doc.scene.lights.back();
    EXPECT_EQ(disk.type, LightType::disk);
    EXPECT_TRUE(disk.shadow);
    EXPECT_DOUBLE_EQ(disk.radius, 0.5);
}

TEST(ExploreFiles, ALoadIsOneUndoStepBackToThePreviousScene) {
    const fs::path dir = fresh_folder("explore_files_load_step");
    Explorer explorer = started();
    ASSERT_TRUE(run(explorer, command::LoadFigure{"fig07"}));
    const std::string file = (dir / "seven.json").string();
    ASSERT_TRUE(run(explorer, command::SaveTo{file}));
    ASSERT_TRUE(run(explorer, command::LoadFigure{"fig05"}));
    commit_edits(explorer);
    const nlohmann::json fig05 = scene_to_json(explorer.doc.scene, PathWriting::absolute());
    ASSERT_TRUE(run(explorer, command::LoadScene{file}));
    commit_edits(explorer);
    EXPECT_EQ(explorer.doc.history.undo_label(), "load " + file);
    ASSERT_TRUE(run(explorer, command::Undo{}));
    EXPECT_EQ(scene_to_json(explorer.doc.scene, PathWriting::absolute()), fig05);
    EXPECT_EQ(explorer.doc.name, "preset fig05");
    EXPECT_EQ(explorer.doc.file, "");
    ASSERT_TRUE(run(explorer, command::Redo{}));
    EXPECT_EQ(explorer.doc.name, file);
    EXPECT_EQ(explorer.doc.file, file) << "a redone load has its file again: Ctrl+S writes it";
}

// A figure preset is no file the user opened: the title names it as a preset
// (not scenes/NAME.json), it has no file, and Ctrl+S asks where to save
// rather than write over the file of the scene it replaced or the repository's.
TEST(ExploreFiles, AFigurePresetHasNoFileAndCtrlSAsks) {
    const fs::path dir = fresh_folder("explore_files_preset_save");
    Explorer explorer = started();
    const std::string file = (dir / "mine.json").string();
    ASSERT_TRUE(run(explorer, command::SaveTo{file}));
    const std::string mine = m3055::test::read_text(file);
    ASSERT_TRUE(run(explorer, command::LoadFigure{"fig06"}));
    EXPECT_EQ(title_name(explorer.doc), "preset fig06");
    EXPECT_EQ(explorer.doc.file, "");
    ASSERT_TRUE(run(explorer, command::ApplyLightPreset{LightPreset::three_point_warm}));
    commit_edits(explorer);
    EXPECT_EQ(title_name(explorer.doc), "preset fig06 * (unsaved edits)");
    EXPECT_EQ(explorer.doc.file, "");
    run(explorer, command::Save{});
    EXPECT_EQ(explorer.view.dialog, Dialog::save_as);
    EXPECT_EQ(explorer.view.save_path, (dir / "fig06.json").string());
    EXPECT_EQ(m3055::test::read_text(file), mine) << "the replaced scene's file is not written";
    // A fig06.json there already (the repository's scenes/ holds every preset's):
    // the proposal is a name that is free.
    std::ofstream(dir / "fig06.json") << "{}";
    std::ofstream(dir / "fig06-2.json") << "{}";
    run(explorer, command::Save{});
    EXPECT_EQ(explorer.view.save_path, (dir / "fig06-3.json").string());
    explorer.session.files.screenshot_dir = dir.string();
    EXPECT_EQ(next_screenshot_path(explorer), (dir / "fig06-0001.png").string()) << "F12 names the preset";
}

// A preset (or a load) over unsaved edits: one Ctrl+Z brings them back, the
// status line says so, and quitting asks first until they are saved; without
// this, Esc after a figure key quit at once and the edits were gone.
TEST(ExploreFiles, APresetOverUnsavedEditsSaysSoAndQuittingAsks) {
    const fs::path dir = fresh_folder("explore_files_replaced_unsaved");
    Explorer explorer = started();
    const std::string file = (dir / "mine.json").string();
    ASSERT_TRUE(run(explorer, command::SaveTo{file}));
    ASSERT_TRUE(run(explorer, command::ApplyLightPreset{LightPreset::three_point_warm}));
    commit_edits(explorer);
    ASSERT_TRUE(unsaved(explorer.doc));
    ASSERT_TRUE(run(explorer, command::LoadFigure{"fig05"}));
    EXPECT_FALSE(unsaved(explorer.doc)) << "the preset as it is built in";
    EXPECT_TRUE(work_unsaved(explorer));
    EXPECT_EQ(explorer.session.replaced_unsaved, file) << "mine.json, by its file";
    EXPECT_NE(explorer.session.messages.status.find("the unsaved edits of mine.json are one Ctrl+Z back"),
              std::string::npos) << explorer.session.messages.status;
    run(explorer, command::AskQuit{});
    EXPECT_FALSE(explorer.session.quit);
    EXPECT_EQ(explorer.view.dialog, Dialog::unsaved_edits);
    explorer.view.dialog = Dialog::none;
    // Back to them and saved: nothing is left to lose.
    ASSERT_TRUE(run(explorer, command::Undo{}));
    ASSERT_TRUE(run(explorer, command::Save{}));
    ASSERT_TRUE(run(explorer, command::LoadFigure{"fig06"}));
    EXPECT_FALSE(work_unsaved(explorer));
    run(explorer, command::AskQuit{});
    EXPECT_TRUE(explorer.session.quit);
}

TEST(ExploreFiles, ScreenshotPathIsTheNextFreeNumberNamedAfterTheSceneFile) {
    const fs::path dir = fresh_folder("explore_files_screenshots");
    Explorer explorer = started();
    explorer.session.files.screenshot_dir = dir.string();
    EXPECT_EQ(next_screenshot_path(explorer), (dir / "m3055-0001.png").string());
    std::ofstream(dir / "m3055-0001.png") << "x";
    std::ofstream(dir / "m3055-0002.json") << "x";  // its PNG missing: still taken
    EXPECT_EQ(next_screenshot_path(explorer), (dir / "m3055-0003.png").string());
    ASSERT_TRUE(run(explorer, command::SaveTo{(dir / "lesson.json").string()}));
    EXPECT_EQ(next_screenshot_path(explorer), (dir / "lesson-0001.png").string());
}

// The page's downloads of an earlier visit are gone from its folder but not
// from the user's: the numbering goes on after them.
TEST(ExploreFiles, ScreenshotPathSkipsNamesThePlatformHandedOutBefore) {
    const fs::path dir = fresh_folder("explore_files_screenshots_taken");
    Explorer explorer = started();
    explorer.session.files.screenshot_dir = dir.string();
    explorer.session.platform.name_taken = [](const std::string& name) {
        return name == "m3055-0001.png" || name == "m3055-0001.json" || name == "m3055-0002.json";
    };
    EXPECT_EQ(next_screenshot_path(explorer), (dir / "m3055-0003.png").string());
}

TEST(ExploreFiles, StartsFromTheNamedSceneFileAsSavedOrTheSpecExample) {
    const fs::path dir = fresh_folder("explore_files_start");
    Explorer plain;
    EXPECT_FALSE(start_scene(plain, "", ""));
    EXPECT_EQ(plain.doc.name, "spec example");
    EXPECT_EQ(scene_to_json(plain.doc.scene, PathWriting::absolute()), scene_to_json(default_scene(), PathWriting::absolute()));
    EXPECT_FALSE(unsaved(plain.doc));
    EXPECT_FALSE(plain.doc.history.can_undo());

    Explorer saved = started();
    ASSERT_TRUE(run(saved, command::LoadFigure{"fig09"}));
    const std::string file = (dir / "nine.json").string();
    ASSERT_TRUE(run(saved, command::SaveTo{file}));
    Explorer named;
    EXPECT_FALSE(start_scene(named, file, ""));
    EXPECT_EQ(named.doc.file, file);
    EXPECT_EQ(named.doc.name, file);
    EXPECT_EQ(scene_to_json(named.doc.scene, PathWriting::absolute()), scene_to_json(saved.doc.scene, PathWriting::absolute()));
    EXPECT_FALSE(unsaved(named.doc));

    Explorer missing;
    EXPECT_THROW(start_scene(missing, (dir / "none.json").string(), ""), std::exception)
        << "without an assignment, a scene file must exist";
}

TEST(ExploreFiles, SaveIntoAMissingFolderFailsAndKeepsTheScenesFile) {
    Explorer explorer = started();
    EXPECT_FALSE(run(explorer, command::SaveTo{(fs::path(::testing::TempDir()) / "no_such_folder" / "x.json").string()}));
    EXPECT_FALSE(explorer.session.messages.error.empty());
    EXPECT_EQ(explorer.doc.file, "");
}

// Save As proposes the scene's own file, or (a figure
// preset loaded since) the preset's name in the folder of the last file, never
// m3055-scene.json in the working folder.
TEST(ExploreFiles, SaveAsProposesTheScenesOwnNameAndFolder) {
    const fs::path dir = fresh_folder("explore_files_save_as");
    Explorer explorer = started();
    const std::string file = (dir / "mine.json").string();
    ASSERT_TRUE(run(explorer, command::SaveTo{file})) << explorer.session.messages.error;
    ASSERT_TRUE(run(explorer, command::LoadScene{file})) << explorer.session.messages.error;
    run(explorer, command::AskSaveAs{});
    EXPECT_EQ(explorer.view.save_path, file);
    ASSERT_TRUE(run(explorer, command::LoadFigure{"fig10"}));
    run(explorer, command::AskSaveAs{});
    EXPECT_EQ(explorer.view.save_path, (dir / "fig10.json").string()) << "the preset's name, the last file's folder";
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
    auto saved_file_field = [&](Explorer& explorer, const std::string& name, std::size_t object) {
        const fs::path path = dir / "work" / name;
        EXPECT_TRUE(run(explorer, command::SaveTo{path.string()})) << explorer.session.messages.error;
        std::ifstream in(path);
        return nlohmann::json::parse(in)["objects"][object]["material"]["file"].get<std::string>();
    };
    Explorer explorer = started();
    ASSERT_TRUE(run(explorer, command::OpenBrdf{(dir / "work" / "mine" / "lambert.brdf").string()})) << explorer.session.messages.brdf_error;
    EXPECT_EQ(saved_file_field(explorer, "desktop.json", 0), (dir / "work" / "mine" / "lambert.brdf").string());
    explorer.session.platform.brdf_paths_relative_to = (dir / "work").string();
    EXPECT_EQ(saved_file_field(explorer, "page.json", 0), "mine/lambert.brdf");
    Explorer loaded = started();
    loaded.session.platform.brdf_paths_relative_to = explorer.session.platform.brdf_paths_relative_to;
    ASSERT_TRUE(run(loaded, command::LoadScene{(dir / "work" / "page.json").string()})) << loaded.session.messages.load_error;
    EXPECT_EQ(saved_file_field(loaded, "again.json", 0), "mine/lambert.brdf") << "loads back from the saved name";
    ASSERT_TRUE(run(explorer, command::OpenBrdf{(dir / "elsewhere.brdf").string()})) << explorer.session.messages.brdf_error;
    EXPECT_EQ(saved_file_field(explorer, "outside.json", 0), (dir / "elsewhere.brdf").string());
}

}  // namespace
}  // namespace m3055::explore
