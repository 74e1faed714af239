// The explorer's undo/redo and its step names, without a window
// (explore/undo.h, explore/operations.h): what the Edit menu shows is what the
// user did, and undoing back to the saved scene leaves nothing unsaved.
#include "explore_started.h"
#include "explore/files.h"
#include "explore/operations.h"
#include "explore/undo.h"
#include "io/message_text.h"
#include "models/model_spec.h"
#include "scene/load.h"
#include "scene/presets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace m3055::explore {
namespace {

// The explorer as `m3055 explore` starts it: the spec example, no history.
using test::started;

// The selected object's material with one number changed, as its slider does.
void set_number(ExplorerState& state, const std::string& name, double value) {
    Material m = *selected_material(state);
    m.set_number(name, value);
    edit_material(state, m);
}

std::string undo_label(const ExplorerState& state) {
    return state.history.can_undo() ? state.history.undo_label() : "";
}

TEST(ExploreUndo, UndoRedoKeepsMoreThan200StepsNamedAfterTheirChange) {
    ExplorerState state = started();
    ASSERT_TRUE(load_figure(state, "fig05"));
    commit_edits(state);
    std::vector<nlohmann::json> after_step = {scene_to_json(state.scene, PathWriting::absolute())};
    for (int i = 1; i <= 250; ++i) {  // 250 steps of m, each a finished slider drag
        set_number(state, "m", 2.0 + i);
        ASSERT_TRUE(commit_edits(state));
        after_step.push_back(scene_to_json(state.scene, PathWriting::absolute()));
    }
    apply_light_preset(state, LightPreset::three_point_warm);
    commit_edits(state);
    EXPECT_EQ(undo_label(state), "light preset three_point_warm");
    ASSERT_TRUE(undo(state));
    EXPECT_EQ(state.history.undo_steps(), 251u);  // the preset and 250 values
    EXPECT_EQ(undo_label(state), "objects[0].material.m 251 -> 252");
    for (int i = 250; i >= 1; --i) {
        ASSERT_TRUE(undo(state)) << i;
        EXPECT_EQ(scene_to_json(state.scene, PathWriting::absolute()), after_step[std::size_t(i) - 1])
            << "after undoing step " << i;
    }
    EXPECT_EQ(undo_label(state), "figure preset fig05");
    for (int i = 1; i <= 250; ++i) {
        ASSERT_TRUE(redo(state)) << i;
        EXPECT_EQ(scene_to_json(state.scene, PathWriting::absolute()), after_step[std::size_t(i)])
            << "after redoing step " << i;
    }
    EXPECT_EQ(state.history.redo_label(), "light preset three_point_warm");
}

TEST(ExploreUndo, HistoryForgetsTheOldestStepsBeyondItsLimit) {
    ExplorerState state = started();
    for (std::size_t i = 1; i <= History::kMaxSteps + 20; ++i) {
        set_number(state, "m", double(i));
        commit_edits(state);
    }
    EXPECT_EQ(state.history.undo_steps(), History::kMaxSteps);
}

TEST(ExploreUndo, ASliderDragIsOneStepFromItsFirstToItsLastValue) {
    ExplorerState state = started();
    const double start = selected_material(state)->number("m");
    for (double m : {12.0, 20.0, 33.0, 40.0}) set_number(state, "m", m);  // frames of one drag
    ASSERT_TRUE(commit_edits(state));
    EXPECT_EQ(state.history.undo_steps(), 1u);
    EXPECT_EQ(undo_label(state), "objects[0].material.m " + text::format_number(start) + " -> 40");
    ASSERT_TRUE(undo(state));
    EXPECT_EQ(selected_material(state)->number("m"), start);
}

TEST(ExploreUndo, ModelSwitchIsNamedAfterTheModelsNotAParameter) {
    ExplorerState state = started();
    set_model(state, "metal");
    commit_edits(state);
    EXPECT_EQ(undo_label(state), "model highlight -> metal");
    set_model(state, "half_lambert");
    commit_edits(state);
    EXPECT_EQ(undo_label(state), "model metal -> half_lambert");
    ASSERT_TRUE(undo(state));
    EXPECT_EQ(state.status, "undid model metal -> half_lambert");
    EXPECT_EQ(selected_material(state)->model().name, "metal");
}

TEST(ExploreUndo, LightEditsAreNamedAfterTheLightsName) {
    ExplorerState state = started();
    apply_light_preset(state, LightPreset::three_point_white);
    commit_edits(state);
    int key = -1;
    for (std::size_t i = 0; i < state.scene.lights.size(); ++i)
        if (state.scene.lights[i].name == "key") key = int(i);
    ASSERT_GE(key, 0);
    Light light = state.scene.lights[std::size_t(key)];
    const double before = light.intensity;
    light.intensity = 0.5;
    edit_light(state, key, light);
    commit_edits(state);
    EXPECT_EQ(undo_label(state), "light key intensity " + text::format_number(before) + " -> 0.5");
}

TEST(ExploreUndo, NamedActionsSayTheirName) {
    ExplorerState state = started();
    add_object(state, Shape::cube);
    commit_edits(state);
    EXPECT_EQ(undo_label(state), "add cube");
    set_model_b(state, "metal_blinn");
    commit_edits(state);
    EXPECT_EQ(undo_label(state), "B model highlight -> metal_blinn");
    copy_a_to_b(state);
    commit_edits(state);
    EXPECT_EQ(undo_label(state), "B = copy of A");
    ASSERT_TRUE(load_figure(state, "fig06"));
    commit_edits(state);
    EXPECT_EQ(undo_label(state), "figure preset fig06");
    set_scene_value(state, "objects[0].material.w", "0.25");
    commit_edits(state);
    EXPECT_EQ(undo_label(state), "objects[0].material.w 1 -> 0.25");
}

TEST(ExploreUndo, Eq14RescaleIsNamedAfterItsButton) {
    ExplorerState state = started();
    set_model(state, "metal");
    set_number(state, "d", 0.2);
    commit_edits(state);
    ASSERT_GT(std::abs(highlight_peak(*selected_material(state)) - 1.0), 1e-3) << "eq. 14 must not hold yet";
    ASSERT_TRUE(rescale_weights_to_eq14(state));
    commit_edits(state);
    EXPECT_EQ(undo_label(state), "rescale weights to eq. 14");
    EXPECT_NEAR(highlight_peak(*selected_material(state)), 1.0, 1e-9);
}

TEST(ExploreUndo, AnEditThatChangesNothingIsNoStep) {
    ExplorerState state = started();
    reset_camera(state);  // already the scene's own camera
    EXPECT_FALSE(commit_edits(state));
    set_number(state, "m", selected_material(state)->number("m"));
    EXPECT_FALSE(commit_edits(state));
    EXPECT_FALSE(state.history.can_undo());
}

TEST(ExploreUndo, UndoingBackToTheSavedSceneLeavesNothingUnsaved) {
    ExplorerState state = started();
    const std::filesystem::path file = std::filesystem::path(::testing::TempDir()) / "explore_undo_saved.json";
    EXPECT_FALSE(unsaved(state));  // the start counts as saved: nothing to lose yet
    ASSERT_TRUE(save_scene(state, file.string()));
    EXPECT_FALSE(unsaved(state));
    EXPECT_EQ(title_name(state), "explore_undo_saved.json");
    set_number(state, "m", 77);
    commit_edits(state);
    EXPECT_TRUE(unsaved(state));
    EXPECT_EQ(title_name(state), "explore_undo_saved.json * (unsaved edits)");
    ASSERT_TRUE(undo(state));
    EXPECT_FALSE(unsaved(state)) << "the scene is its file again";
    ASSERT_TRUE(redo(state));
    EXPECT_TRUE(unsaved(state));
    std::filesystem::remove(file);
}

// The status line tells only the last action: an edit
// after an undo clears "undid ..." (no stale "redid ... m" after a model switch).
TEST(ExploreUndo, AnEditClearsTheLastActionsStatus) {
    ExplorerState state;
    set_scene(state, default_scene(), "spec example");
    start_history(state);
    Material m = *selected_material(state);
    m.set_number("m", 40);
    edit_material(state, m);
    commit_edits(state);
    ASSERT_TRUE(undo(state));
    EXPECT_NE(state.status.find("undid"), std::string::npos);
    set_model(state, "metal");
    EXPECT_EQ(state.status, "");
}

// Shift+drag on the display moves the selected object in
// the plane facing the camera so it follows the mouse (a drag across the
// display's height is the view's height at the object's depth: 2 d tan(fov/2)
// in perspective, the camera's height orthographic); a whole drag is one undo step.
TEST(ExploreUndo, ShiftDragMovesTheSelectedObjectInTheViewPlaneInOneStep) {
    ExplorerState state = started();
    Camera& c = state.scene.camera;
    c.projection = Projection::perspective;
    c.position = {0, 0, 10};
    c.target = {0, 0, 0};
    c.up = {0, 1, 0};
    c.fov_y_deg = 30.0;
    state.scene.objects[0].center = {0, 0, 0};
    commit_edits(state);
    const std::size_t steps = state.history.undo_steps();
    const double shown_h = 320.0, per_unit = 2.0 * 10.0 * std::tan(15.0 * 3.14159265358979323846 / 180.0) / shown_h;
    for (int frame = 0; frame < 4; ++frame) move_object_in_view(state, 10.0, -5.0, shown_h);  // right and up
    EXPECT_NEAR(state.scene.objects[0].center.x, 40.0 * per_unit, 1e-12);
    EXPECT_NEAR(state.scene.objects[0].center.y, 20.0 * per_unit, 1e-12);
    EXPECT_NEAR(state.scene.objects[0].center.z, 0.0, 1e-12) << "in the view plane";
    ASSERT_TRUE(commit_edits(state));
    EXPECT_EQ(state.history.undo_steps(), steps + 1) << "one drag, one step";
    ASSERT_TRUE(undo(state));
    EXPECT_EQ(state.scene.objects[0].center, dvec3(0, 0, 0));
    state.scene.camera.projection = Projection::orthographic;
    state.scene.camera.height = 4.0;
    move_object_in_view(state, shown_h, 0.0, shown_h);
    EXPECT_NEAR(state.scene.objects[0].center.x, 4.0, 1e-12) << "orthographic: the camera's height";
}

}  // namespace
}  // namespace m3055::explore
