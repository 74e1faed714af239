// Which key does what in the explorer (explore/keys.h), without a window: a
// plain digit never replaces an edited scene, Ctrl+digit does (undoably), and
// no shortcut steals a key from a text field.
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

ExplorerState started() {
    ExplorerState state;
    set_scene(state, default_scene(), "spec example");
    start_history(state);
    return state;
}

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

TEST(ExploreKeys, DigitsPickTheFigurePresetsInThePapersOrder) {
    EXPECT_STREQ(figure_for_digit(0), "spec_example");
    EXPECT_STREQ(figure_for_digit(1), "fig05");
    EXPECT_STREQ(figure_for_digit(9), "fig13");
    ExplorerState state = started();
    EXPECT_TRUE(handle_shortcut(state, key("2")));
    EXPECT_EQ(state.scene_name, "scenes/fig06.json");
    EXPECT_FALSE(unsaved(state)) << "a preset has nothing to lose: digits may flip through the figures";
    EXPECT_TRUE(handle_shortcut(state, key("3")));
    EXPECT_EQ(state.scene_name, "scenes/fig07.json");
}

TEST(ExploreKeys, APlainDigitNeverReplacesAnEditedScene) {
    ExplorerState state = started();
    ASSERT_TRUE(handle_shortcut(state, key("1")));
    edit_m(state, 40);
    const nlohmann::json edited = scene_to_json(state.scene);
    for (const char* digit : {"0", "6"}) {  // "0.6" typed with no field active
        EXPECT_FALSE(handle_shortcut(state, key(digit))) << digit;
        EXPECT_EQ(scene_to_json(state.scene), edited) << digit;
    }
    EXPECT_NE(state.status.find("ignored: the scene has unsaved edits"), std::string::npos) << state.status;
}

TEST(ExploreKeys, UndoingBackToAPresetLetsDigitsFlipThroughFiguresAgain) {
    ExplorerState state = started();
    ASSERT_TRUE(load_figure(state, "fig05"));
    commit_edits(state);
    edit_m(state, 40);
    ASSERT_TRUE(undo(state));  // back to the preset as it came: nothing to lose again
    EXPECT_TRUE(handle_shortcut(state, key("2")));
    EXPECT_EQ(state.scene_name, "scenes/fig06.json");
}

TEST(ExploreKeys, CtrlDigitReplacesAnEditedSceneUndoably) {
    ExplorerState state = started();
    edit_m(state, 40);
    const nlohmann::json edited = scene_to_json(state.scene);
    ASSERT_TRUE(handle_shortcut(state, key("ctrl+2")));
    commit_edits(state);
    EXPECT_EQ(state.scene_name, "scenes/fig06.json");
    EXPECT_EQ(state.history.undo_label(), "figure preset fig06");
    ASSERT_TRUE(undo(state));
    EXPECT_EQ(scene_to_json(state.scene), edited);
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
