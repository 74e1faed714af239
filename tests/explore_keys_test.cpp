// Which key does what in the explorer (explore/keys.h), without a window: a
// plain digit never replaces the scene (edited or just saved), Ctrl+digit does
// (undoably), "unsaved" is whether the scene differs from its file, Save As
// never proposes the file of a replaced scene, and no shortcut steals a key
// from a text field.
#include "explore_started.h"
#include "explore/files.h"
#include "explore/keys.h"
#include "explore/operations.h"
#include "explore/undo.h"
#include "scene/load.h"
#include "scene/presets.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace m3055::explore {
namespace {

using test::started;

KeyPress key(const std::string& name) {
    const std::optional<KeyPress> press = parse_key_name(name);
    EXPECT_TRUE(press) << name;
    return press.value_or(KeyPress{});
}

void edit_m(ExplorerState& state, double m) {
    Material edited = *selected_material(state);
    edited.set_number("m", m);
    edit_material(state, edited);
    commit_edits(state);
}

TEST(ExploreKeys, CtrlDigitsPickTheFigurePresetsInThePapersOrder) {
    EXPECT_STREQ(figure_for_digit(0), "spec_example");
    EXPECT_STREQ(figure_for_digit(1), "fig05");
    EXPECT_STREQ(figure_for_digit(9), "fig13");
    ExplorerState state = started();
    EXPECT_TRUE(handle_shortcut(state, key("ctrl+2")));
    EXPECT_EQ(state.scene_name, "scenes/fig06.json");
    EXPECT_FALSE(unsaved(state)) << "a preset as it came has nothing to lose";
    EXPECT_TRUE(handle_shortcut(state, key("ctrl+3")));
    EXPECT_EQ(state.scene_name, "scenes/fig07.json");
}

TEST(ExploreKeys, APlainDigitNeverReplacesTheSceneEditedOrNot) {
    ExplorerState state = started();
    const nlohmann::json fresh = scene_to_json(state.scene, PathWriting::absolute());
    for (const char* digit : {"0", "6"}) {  // "0.6" typed with no field active, nothing edited
        EXPECT_FALSE(handle_shortcut(state, key(digit))) << digit;
        EXPECT_EQ(scene_to_json(state.scene, PathWriting::absolute()), fresh) << digit;
        EXPECT_EQ(state.scene_name, "spec example");
    }
    EXPECT_NE(state.status.find("Ctrl+6"), std::string::npos) << "the status says what does: " << state.status;
    ASSERT_TRUE(handle_shortcut(state, key("ctrl+1")));
    edit_m(state, 40);
    const nlohmann::json edited = scene_to_json(state.scene, PathWriting::absolute());
    for (const char* digit : {"0", "6"}) {
        EXPECT_FALSE(handle_shortcut(state, key(digit))) << digit;
        EXPECT_EQ(scene_to_json(state.scene, PathWriting::absolute()), edited) << digit;
    }
}

// The student: a saved practice scene, then a stray "0.6".
TEST(ExploreKeys, AJustSavedSceneSurvivesAStrayNumberAndUndoBackToItIsClean) {
    ExplorerState state = started();
    const std::string file = ::testing::TempDir() + "explore_keys_mine.json";
    std::remove(file.c_str());
    edit_m(state, 40);
    ASSERT_TRUE(save_scene(state, file));
    ASSERT_FALSE(unsaved(state));
    const nlohmann::json saved = scene_to_json(state.scene, PathWriting::absolute());
    EXPECT_FALSE(handle_shortcut(state, key("0")));
    EXPECT_FALSE(handle_shortcut(state, key("6")));
    EXPECT_EQ(scene_to_json(state.scene, PathWriting::absolute()), saved);
    EXPECT_EQ(state.scene_file, file);
    EXPECT_FALSE(unsaved(state));

    // Ctrl+6 on purpose: Fig. 10, Save As proposes fig10.json beside mine, not mine.
    ASSERT_TRUE(handle_shortcut(state, key("ctrl+6")));
    commit_edits(state);
    EXPECT_TRUE(handle_shortcut(state, key("ctrl+s")));
    EXPECT_TRUE(state.save_as_requested);
    EXPECT_EQ(state.save_path, ::testing::TempDir() + "fig10.json");
    EXPECT_FALSE(save_as(state, file)) << "an existing other file: asked twice";
    EXPECT_NE(state.error.find("exists"), std::string::npos) << state.error;
    EXPECT_EQ(load_scene_file(file, LoadContext::trusted()).objects[0].material.number("m"), 40.0);

    // Undo back to the saved scene: clean, its own file again.
    ASSERT_TRUE(undo(state));
    EXPECT_EQ(scene_to_json(state.scene, PathWriting::absolute()), saved);
    EXPECT_EQ(state.scene_file, file);
    EXPECT_FALSE(unsaved(state)) << "identical to the file: nothing unsaved";
    edit_m(state, 41);
    EXPECT_TRUE(unsaved(state));
    edit_m(state, 40);  // set back by hand: the same as the file again
    EXPECT_FALSE(unsaved(state));
    std::remove(file.c_str());
}

TEST(ExploreKeys, SaveAsOverwritesAnotherFileOnlyWhenAskedTwice) {
    ExplorerState state = started();
    const std::string other = ::testing::TempDir() + "explore_keys_other.json";
    {
        ExplorerState writer = started();
        ASSERT_TRUE(save_scene(writer, other));
    }
    edit_m(state, 40);
    request_save_as(state);
    EXPECT_EQ(state.save_path, "m3055-scene.json") << "no file yet, nothing loaded: the default name";
    EXPECT_FALSE(save_as(state, other));
    EXPECT_TRUE(save_as(state, other)) << "the second Save overwrites";
    EXPECT_EQ(state.scene_file, other);
    edit_m(state, 41);
    EXPECT_TRUE(save_as(state, other)) << "the scene's own file: no question";
    request_save_as(state);
    EXPECT_EQ(state.save_path, other) << "Save As proposes the scene's own file";
    std::remove(other.c_str());
}

TEST(ExploreKeys, CtrlDigitReplacesAnEditedSceneUndoably) {
    ExplorerState state = started();
    edit_m(state, 40);
    const nlohmann::json edited = scene_to_json(state.scene, PathWriting::absolute());
    ASSERT_TRUE(handle_shortcut(state, key("ctrl+2")));
    commit_edits(state);
    EXPECT_EQ(state.scene_name, "scenes/fig06.json");
    EXPECT_EQ(state.history.undo_label(), "figure preset fig06");
    ASSERT_TRUE(undo(state));
    EXPECT_EQ(scene_to_json(state.scene, PathWriting::absolute()), edited);
}

TEST(ExploreKeys, CtrlSAsksForAFileFirstThenWritesTheScenesOwnFile) {
    ExplorerState state = started();
    const std::string file = ::testing::TempDir() + "explore_keys_saved.json";
    edit_m(state, 40);
    EXPECT_TRUE(handle_shortcut(state, key("ctrl+s")));
    EXPECT_TRUE(state.save_as_requested) << "no file of its own yet: Save As";
    EXPECT_TRUE(unsaved(state));
    ASSERT_TRUE(save_scene(state, file));  // the Save As dialog's choice
    EXPECT_FALSE(unsaved(state));
    edit_m(state, 41);
    EXPECT_FALSE(handle_shortcut(state, key("0")));
    EXPECT_EQ(state.scene_file, file);
    ASSERT_TRUE(handle_shortcut(state, key("ctrl+s")));  // its own file now: written, no dialog
    EXPECT_FALSE(unsaved(state));
    std::remove(file.c_str());
}

TEST(ExploreKeys, NoShortcutWhileATextFieldIsTypedInto) {
    ExplorerState state = started();
    KeyFocus typing;
    typing.text_input = true;
    for (const char* name : {"1", "ctrl+1", "ctrl+z", "escape", "r", "f1"})
        EXPECT_FALSE(handle_shortcut(state, key(name), typing)) << name;
    EXPECT_EQ(state.scene_name, "spec example");
    EXPECT_FALSE(state.quit_requested);
}

TEST(ExploreKeys, SingleKeysWaitWhileAWidgetTakesTheKeyboardButCtrlShortcutsDoNot) {
    ExplorerState state = started();
    KeyFocus slider_held;
    slider_held.item_active = true;
    EXPECT_FALSE(handle_shortcut(state, key("escape"), slider_held));
    EXPECT_FALSE(handle_shortcut(state, key("1"), slider_held));
    EXPECT_TRUE(handle_shortcut(state, key("ctrl+1"), slider_held));
    EXPECT_EQ(state.scene_name, "scenes/fig05.json");
}

TEST(ExploreKeys, EscAsksToQuitF1TogglesPanelsF12AsksForAScreenshotRResetsTheCamera) {
    ExplorerState state = started();
    EXPECT_TRUE(handle_shortcut(state, key("escape")));
    EXPECT_TRUE(state.quit_requested);
    EXPECT_FALSE(state.quit) << "Esc asks first (the dialog decides)";
    EXPECT_TRUE(handle_shortcut(state, key("f1")));
    EXPECT_FALSE(state.show_panels);
    EXPECT_TRUE(handle_shortcut(state, key("f12")));
    EXPECT_TRUE(state.screenshot_requested);
    orbit_camera(state, 120, 30);
    EXPECT_NE(state.scene.camera.position, state.camera_home.position);
    EXPECT_TRUE(handle_shortcut(state, key("r")));
    EXPECT_EQ(state.scene.camera.position, state.camera_home.position);
}

TEST(ExploreKeys, CtrlZUndoesCtrlShiftZAndCtrlYRedo) {
    ExplorerState state = started();
    edit_m(state, 40);
    EXPECT_TRUE(handle_shortcut(state, key("ctrl+z")));
    EXPECT_NE(selected_material(state)->number("m"), 40);
    EXPECT_TRUE(handle_shortcut(state, key("ctrl+shift+z")));
    EXPECT_EQ(selected_material(state)->number("m"), 40);
    EXPECT_TRUE(handle_shortcut(state, key("ctrl+z")));
    EXPECT_TRUE(handle_shortcut(state, key("ctrl+y")));
    EXPECT_EQ(selected_material(state)->number("m"), 40);
}

TEST(ExploreKeys, KeyNamesParseAsTheScriptWritesThem) {
    EXPECT_FALSE(parse_key_name("ctrl+"));
    EXPECT_FALSE(parse_key_name("f13"));
    const KeyPress redo_key = key("Ctrl+Shift+Z");
    EXPECT_TRUE(redo_key.ctrl);
    EXPECT_TRUE(redo_key.shift);
    EXPECT_EQ(redo_key.key, Key::z);
    EXPECT_EQ(key("7").digit, 7);
    EXPECT_EQ(key("q").key, Key::other);
}

}  // namespace
}  // namespace m3055::explore
