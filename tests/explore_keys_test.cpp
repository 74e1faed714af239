// Which key does what in the explorer (explore/keys.h), without a window: a
// plain digit never replaces the scene (edited or just saved), Ctrl+digit does
// (undoably), "unsaved" is whether the scene differs from its file, Save As
// never proposes the file of a replaced scene, and no shortcut steals a key
// from a text field.
#include "explore_started.h"
#include "explore/files.h"
#include "explore/keys.h"
#include "explore/operations.h"
#include "scene/load.h"
#include "scene/presets.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace m3055::explore {
namespace {

using test::run;
using test::started;

KeyPress key(const std::string& name) {
    const std::optional<KeyPress> press = parse_key_name(name);
    EXPECT_TRUE(press) << name;
    return press.value_or(KeyPress{});
}

// The key pressed, then the frame's commands applied.
bool press(Explorer& explorer, const std::string& name, const KeyFocus& focus = {}) {
    const bool handled = handle_shortcut(explorer, key(name), focus);
    apply_commands(explorer);
    return handled;
}

void edit_m(Explorer& explorer, double m) {
    Material edited = *selected_material(explorer);
    edited.set_number("m", m);
    run(explorer, command::SetMaterial{explorer.view.selected_object, edited, ""});
    commit_edits(explorer);
}

TEST(ExploreKeys, CtrlDigitsPickTheFigurePresetsInThePapersOrder) {
    EXPECT_STREQ(figure_for_digit(0), "spec_example");
    EXPECT_STREQ(figure_for_digit(1), "fig05");
    EXPECT_STREQ(figure_for_digit(9), "fig13");
    Explorer explorer = started();
    EXPECT_TRUE(press(explorer, "ctrl+2"));
    EXPECT_EQ(explorer.doc.name, "preset fig06");
    EXPECT_FALSE(unsaved(explorer.doc)) << "a preset as it came has nothing to lose";
    EXPECT_TRUE(press(explorer, "ctrl+3"));
    EXPECT_EQ(explorer.doc.name, "preset fig07");
}

// In a browser Ctrl+digit switches tabs and Ctrl+0 resets the zoom: the
// page's chord is Ctrl+Alt, and its plain Ctrl+digit leaves the scene alone.
TEST(ExploreKeys, ThePagesFigureKeysAreCtrlAltDigitsAndItsCtrlDigitsTheBrowsers) {
    Explorer explorer = started();
    explorer.session.platform.figure_chord = FigureChord::ctrl_alt;
    const nlohmann::json fresh = scene_to_json(explorer.doc.scene, PathWriting::absolute());
    EXPECT_FALSE(press(explorer, "ctrl+2"));
    EXPECT_EQ(scene_to_json(explorer.doc.scene, PathWriting::absolute()), fresh);
    EXPECT_EQ(explorer.doc.name, "spec example");
    EXPECT_TRUE(press(explorer, "ctrl+alt+2"));
    EXPECT_EQ(explorer.doc.name, "preset fig06");
    EXPECT_FALSE(press(explorer, "6"));
    EXPECT_NE(explorer.session.messages.status.find("Ctrl+Alt+6"), std::string::npos) << explorer.session.messages.status;
    EXPECT_TRUE(press(explorer, "ctrl+z")) << "the other Ctrl shortcuts stay the explorer's";
    EXPECT_EQ(explorer.doc.name, "spec example");
}

TEST(ExploreKeys, APlainDigitNeverReplacesTheSceneEditedOrNot) {
    Explorer explorer = started();
    const nlohmann::json fresh = scene_to_json(explorer.doc.scene, PathWriting::absolute());
    for (const char* digit : {"0", "6"}) {  // "0.6" typed with no field active, nothing edited
        EXPECT_FALSE(press(explorer, digit)) << digit;
        EXPECT_EQ(scene_to_json(explorer.doc.scene, PathWriting::absolute()), fresh) << digit;
        EXPECT_EQ(explorer.doc.name, "spec example");
    }
    EXPECT_NE(explorer.session.messages.status.find("Ctrl+6"), std::string::npos) << "the status says what does: " << explorer.session.messages.status;
    ASSERT_TRUE(press(explorer, "ctrl+1"));
    edit_m(explorer, 40);
    const nlohmann::json edited = scene_to_json(explorer.doc.scene, PathWriting::absolute());
    for (const char* digit : {"0", "6"}) {
        EXPECT_FALSE(press(explorer, digit)) << digit;
        EXPECT_EQ(scene_to_json(explorer.doc.scene, PathWriting::absolute()), edited) << digit;
    }
}

// The student: a saved practice scene, then a stray "0.6".
TEST(ExploreKeys, AJustSavedSceneSurvivesAStrayNumberAndUndoBackToItIsClean) {
    Explorer explorer = started();
    const std::string file = ::testing::TempDir() + "explore_keys_mine.json";
    std::remove(file.c_str());
    edit_m(explorer, 40);
    ASSERT_TRUE(run(explorer, command::SaveTo{file}));
    ASSERT_FALSE(unsaved(explorer.doc));
    const nlohmann::json saved = scene_to_json(explorer.doc.scene, PathWriting::absolute());
    EXPECT_FALSE(press(explorer, "0"));
    EXPECT_FALSE(press(explorer, "6"));
    EXPECT_EQ(scene_to_json(explorer.doc.scene, PathWriting::absolute()), saved);
    EXPECT_EQ(explorer.doc.file, file);
    EXPECT_FALSE(unsaved(explorer.doc));

    // Ctrl+6 on purpose: Fig. 10, Save As proposes fig10.json beside mine, not mine.
    ASSERT_TRUE(press(explorer, "ctrl+6"));
    commit_edits(explorer);
    EXPECT_TRUE(press(explorer, "ctrl+s"));
    EXPECT_EQ(explorer.view.dialog, Dialog::save_as);
    EXPECT_EQ(explorer.view.save_path, ::testing::TempDir() + "fig10.json");
    EXPECT_FALSE(run(explorer, command::SaveAs{file})) << "an existing other file: asked twice";
    EXPECT_NE(explorer.session.messages.error.find("exists"), std::string::npos) << explorer.session.messages.error;
    EXPECT_EQ(load_scene_file(file, LoadContext::trusted()).objects[0].material.number("m"), 40.0);

    // Undo back to the saved scene: clean, its own file again.
    ASSERT_TRUE(run(explorer, command::Undo{}));
    EXPECT_EQ(scene_to_json(explorer.doc.scene, PathWriting::absolute()), saved);
    EXPECT_EQ(explorer.doc.file, file);
    EXPECT_FALSE(unsaved(explorer.doc)) << "identical to the file: nothing unsaved";
    edit_m(explorer, 41);
    EXPECT_TRUE(unsaved(explorer.doc));
    // Set back by hand: an edit since the save, as in any editor (revisions, not contents, are compared).
    edit_m(explorer, 40);
    EXPECT_TRUE(unsaved(explorer.doc));
    std::remove(file.c_str());
}

TEST(ExploreKeys, SaveAsOverwritesAnotherFileOnlyWhenAskedTwice) {
    Explorer explorer = started();
    const std::string other = ::testing::TempDir() + "explore_keys_other.json";
    {
        Explorer writer = started();
        ASSERT_TRUE(run(writer, command::SaveTo{other}));
    }
    edit_m(explorer, 40);
    run(explorer, command::AskSaveAs{});
    EXPECT_EQ(explorer.view.save_path, "m3055-scene.json") << "no file yet, nothing loaded: the default name";
    EXPECT_FALSE(run(explorer, command::SaveAs{other}));
    EXPECT_TRUE(run(explorer, command::SaveAs{other})) << "the second Save overwrites";
    EXPECT_EQ(explorer.doc.file, other);
    edit_m(explorer, 41);
    EXPECT_TRUE(run(explorer, command::SaveAs{other})) << "the scene's own file: no question";
    run(explorer, command::AskSaveAs{});
    EXPECT_EQ(explorer.view.save_path, other) << "Save As proposes the scene's own file";
    std::remove(other.c_str());
}

TEST(ExploreKeys, CtrlDigitReplacesAnEditedSceneUndoably) {
    Explorer explorer = started();
    edit_m(explorer, 40);
    const nlohmann::json edited = scene_to_json(explorer.doc.scene, PathWriting::absolute());
    ASSERT_TRUE(press(explorer, "ctrl+2"));
    commit_edits(explorer);
    EXPECT_EQ(explorer.doc.name, "preset fig06");
    EXPECT_EQ(explorer.doc.history.undo_label(), "figure preset fig06");
    ASSERT_TRUE(run(explorer, command::Undo{}));
    EXPECT_EQ(scene_to_json(explorer.doc.scene, PathWriting::absolute()), edited);
}

TEST(ExploreKeys, CtrlSAsksForAFileFirstThenWritesTheScenesOwnFile) {
    Explorer explorer = started();
    const std::string file = ::testing::TempDir() + "explore_keys_saved.json";
    edit_m(explorer, 40);
    EXPECT_TRUE(press(explorer, "ctrl+s"));
    EXPECT_EQ(explorer.view.dialog, Dialog::save_as) << "no file of its own yet: Save As";
    EXPECT_TRUE(unsaved(explorer.doc));
    ASSERT_TRUE(run(explorer, command::SaveTo{file}));  // the Save As dialog's choice
    EXPECT_FALSE(unsaved(explorer.doc));
    edit_m(explorer, 41);
    EXPECT_FALSE(press(explorer, "0"));
    EXPECT_EQ(explorer.doc.file, file);
    ASSERT_TRUE(press(explorer, "ctrl+s"));  // its own file now: written, no dialog
    EXPECT_FALSE(unsaved(explorer.doc));
    std::remove(file.c_str());
}

TEST(ExploreKeys, NoShortcutWhileATextFieldIsTypedInto) {
    Explorer explorer = started();
    KeyFocus typing;
    typing.text_input = true;
    for (const char* name : {"1", "ctrl+1", "ctrl+z", "escape", "r", "f1"})
        EXPECT_FALSE(press(explorer, name, typing)) << name;
    EXPECT_EQ(explorer.doc.name, "spec example");
    EXPECT_FALSE(explorer.session.quit);
    EXPECT_EQ(explorer.view.dialog, Dialog::none);
}

TEST(ExploreKeys, SingleKeysWaitWhileAWidgetTakesTheKeyboardButCtrlShortcutsDoNot) {
    Explorer explorer = started();
    KeyFocus slider_held;
    slider_held.item_active = true;
    EXPECT_FALSE(press(explorer, "escape", slider_held));
    EXPECT_FALSE(press(explorer, "1", slider_held));
    EXPECT_TRUE(press(explorer, "ctrl+1", slider_held));
    EXPECT_EQ(explorer.doc.name, "preset fig05");
}

TEST(ExploreKeys, EscQuitsAskingFirstWhenEditedF1TogglesPanelsF12AsksForAScreenshotRResetsTheCamera) {
    Explorer explorer = started();
    edit_m(explorer, 40);
    EXPECT_TRUE(press(explorer, "escape"));
    EXPECT_EQ(explorer.view.dialog, Dialog::unsaved_edits);
    EXPECT_FALSE(explorer.session.quit) << "Esc asks first (the dialog decides)";
    ASSERT_TRUE(run(explorer, command::Undo{}));
    explorer.view.dialog = Dialog::none;
    EXPECT_TRUE(press(explorer, "escape"));
    EXPECT_TRUE(explorer.session.quit) << "nothing to lose: Esc quits";
    EXPECT_TRUE(press(explorer, "f1"));
    EXPECT_FALSE(explorer.view.show_panels);
    EXPECT_TRUE(press(explorer, "f12"));
    ASSERT_EQ(explorer.display_requests.size(), 1u);
    EXPECT_TRUE(std::holds_alternative<command::Screenshot>(explorer.display_requests[0]));
    run(explorer, command::OrbitCamera{120, 30});
    EXPECT_NE(explorer.doc.scene.camera.position, explorer.doc.camera_home.position);
    EXPECT_TRUE(press(explorer, "r"));
    EXPECT_EQ(explorer.doc.scene.camera.position, explorer.doc.camera_home.position);
}

TEST(ExploreKeys, CtrlZUndoesCtrlShiftZAndCtrlYRedo) {
    Explorer explorer = started();
    edit_m(explorer, 40);
    EXPECT_TRUE(press(explorer, "ctrl+z"));
    EXPECT_NE(selected_material(explorer)->number("m"), 40);
    EXPECT_TRUE(press(explorer, "ctrl+shift+z"));
    EXPECT_EQ(selected_material(explorer)->number("m"), 40);
    EXPECT_TRUE(press(explorer, "ctrl+z"));
    EXPECT_TRUE(press(explorer, "ctrl+y"));
    EXPECT_EQ(selected_material(explorer)->number("m"), 40);
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
