// The explorer's undo/redo and its step names, without a window
// (explore/edits.h, explore/operations.h): what the Edit menu shows is what the
// user did, and undoing back to the saved scene leaves nothing unsaved.
#include "explore_started.h"
#include "explore/files.h"
#include "explore/operations.h"
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
using test::run;
using test::started;

// The selected object's material with one number changed, as its slider does.
void set_number(Explorer& explorer, const std::string& name, double value) {
    Material m = *selected_material(explorer);
    m.set_number(name, value);
    run(explorer, command::SetMaterial{explorer.view.selected_object, m, ""});
}

std::string undo_label(const Explorer& explorer) {
    return explorer.doc.history.can_undo() ? explorer.doc.history.undo_label() : "";
}

TEST(ExploreUndo, UndoRedoKeepsMoreThan200StepsNamedAfterTheirChange) {
    Explorer explorer = started();
    ASSERT_TRUE(run(explorer, command::LoadFigure{"fig05"}));
    commit_edits(explorer);
    std::vector<nlohmann::json> after_step = {scene_to_json(explorer.doc.scene, PathWriting::absolute())};
    for (int i = 1; i <= 250; ++i) {  // 250 steps of m, each a finished slider drag
        set_number(explorer, "m", 2.0 + i);
        ASSERT_TRUE(commit_edits(explorer));
        after_step.push_back(scene_to_json(explorer.doc.scene, PathWriting::absolute()));
    }
    run(explorer, command::ApplyLightPreset{LightPreset::three_point_warm});
    commit_edits(explorer);
    EXPECT_EQ(undo_label(explorer), "light preset three_point_warm");
    ASSERT_TRUE(run(explorer, command::Undo{}));
    EXPECT_EQ(explorer.doc.history.undo_steps(), 251u);  // the preset and 250 values
    EXPECT_EQ(undo_label(explorer), "objects[0].material.m 251 -> 252");
    for (int i = 250; i >= 1; --i) {
        ASSERT_TRUE(run(explorer, command::Undo{})) << i;
        EXPECT_EQ(scene_to_json(explorer.doc.scene, PathWriting::absolute()), after_step[std::size_t(i) - 1]) << "after undoing step " << i;
    }
    EXPECT_EQ(undo_label(explorer), "figure preset fig05");
    for (int i = 1; i <= 250; ++i) {
        ASSERT_TRUE(run(explorer, command::Redo{})) << i;
        EXPECT_EQ(scene_to_json(explorer.doc.scene, PathWriting::absolute()), after_step[std::size_t(i)]) << "after redoing step " << i;
    }
    EXPECT_EQ(explorer.doc.history.redo_label(), "light preset three_point_warm");
}

TEST(ExploreUndo, HistoryForgetsTheOldestStepsBeyondItsLimit) {
    Explorer explorer = started();
    for (std::size_t i = 1; i <= History::kMaxSteps + 20; ++i) {
        set_number(explorer, "m", double(i));
        commit_edits(explorer);
    }
    EXPECT_EQ(explorer.doc.history.undo_steps(), History::kMaxSteps);
}

TEST(ExploreUndo, ASliderDragIsOneStepFromItsFirstToItsLastValue) {
    Explorer explorer = started();
    const double start = selected_material(explorer)->number("m");
    for (double m : {12.0, 20.0, 33.0, 40.0}) set_number(explorer, "m", m);  // frames of one drag
    ASSERT_TRUE(commit_edits(explorer));
    EXPECT_EQ(explorer.doc.history.undo_steps(), 1u);
    EXPECT_EQ(undo_label(explorer), "objects[0].material.m " + text::format_number(start) + " -> 40");
    ASSERT_TRUE(run(explorer, command::Undo{}));
    EXPECT_EQ(selected_material(explorer)->number("m"), start);
}

TEST(ExploreUndo, ModelSwitchIsNamedAfterTheModelsNotAParameter) {
    Explorer explorer = started();
    run(explorer, command::SetMaterial{explorer.view.selected_object, with_model_named(*selected_material(explorer), "metal"), ""});
    commit_edits(explorer);
    EXPECT_EQ(undo_label(explorer), "model highlight -> metal");
    run(explorer, command::SetMaterial{explorer.view.selected_object, with_model_named(*selected_material(explorer), "half_lambert"), ""});
    commit_edits(explorer);
    EXPECT_EQ(undo_label(explorer), "model metal -> half_lambert");
    ASSERT_TRUE(run(explorer, command::Undo{}));
    EXPECT_EQ(explorer.session.messages.status, "undid model metal -> half_lambert");
    EXPECT_EQ(selected_material(explorer)->model().name, "metal");
}

TEST(ExploreUndo, LightEditsAreNamedAfterTheLightsName) {
    Explorer explorer = started();
    run(explorer, command::ApplyLightPreset{LightPreset::three_point_white});
    commit_edits(explorer);
    int key = -1;
    for (std::size_t i = 0; i < explorer.doc.scene.lights.size(); ++i)
        if (explorer.doc.scene.lights[i].name == "key") key = int(i);
    ASSERT_GE(key, 0);
    Light light = explorer.doc.scene.lights[std::size_t(key)];
    const double before = light.intensity;
    light.intensity = 0.5;
    run(explorer, command::SetLight{key, light});
    commit_edits(explorer);
    EXPECT_EQ(undo_label(explorer), "light key intensity " + text::format_number(before) + " -> 0.5");
}

TEST(ExploreUndo, NamedActionsSayTheirName) {
    Explorer explorer = started();
    run(explorer, command::AddObject{Shape::cube});
    commit_edits(explorer);
    EXPECT_EQ(undo_label(explorer), "add cube");
    run(explorer, command::SetMaterial{kMaterialB, with_model_named(explorer.doc.material_b, "metal_blinn"), ""});
    commit_edits(explorer);
    EXPECT_EQ(undo_label(explorer), "B model highlight -> metal_blinn");
    run(explorer, command::CopyAToB{});
    commit_edits(explorer);
    EXPECT_EQ(undo_label(explorer), "B = copy of A");
    ASSERT_TRUE(run(explorer, command::LoadFigure{"fig06"}));
    commit_edits(explorer);
    EXPECT_EQ(undo_label(explorer), "figure preset fig06");
    run(explorer, command::SetSceneValue{"objects[0].material.w", "0.25"});
    commit_edits(explorer);
    EXPECT_EQ(undo_label(explorer), "objects[0].material.w 1 -> 0.25");
}

TEST(ExploreUndo, Eq14RescaleIsNamedAfterItsButton) {
    Explorer explorer = started();
    run(explorer, command::SetMaterial{explorer.view.selected_object, with_model_named(*selected_material(explorer), "metal"), ""});
    set_number(explorer, "d", 0.2);
    commit_edits(explorer);
    ASSERT_GT(std::abs(highlight_peak(*selected_material(explorer)) - 1.0), 1e-3) << "eq. 14 must not hold yet";
    Material rescaled;
    ASSERT_TRUE(eq14_rescaled(*selected_material(explorer), &rescaled));
    run(explorer, command::SetMaterial{explorer.view.selected_object, rescaled, kEq14Action});
    commit_edits(explorer);
    EXPECT_EQ(undo_label(explorer), "rescale weights to eq. 14");
    EXPECT_NEAR(highlight_peak(*selected_material(explorer)), 1.0, 1e-9);
}

TEST(ExploreUndo, AnEditThatChangesNothingIsNoStep) {
    Explorer explorer = started();
    run(explorer, command::ResetCamera{});  // already the scene's own camera
    EXPECT_FALSE(commit_edits(explorer));
    set_number(explorer, "m", selected_material(explorer)->number("m"));
    EXPECT_FALSE(commit_edits(explorer));
    EXPECT_FALSE(explorer.doc.history.can_undo());
}

TEST(ExploreUndo, UndoingBackToTheSavedSceneLeavesNothingUnsaved) {
    Explorer explorer = started();
    const std::filesystem::path file = std::filesystem::path(::testing::TempDir()) / "explore_undo_saved.json";
    EXPECT_FALSE(unsaved(explorer.doc));  // the start counts as saved: nothing to lose yet
    ASSERT_TRUE(run(explorer, command::SaveTo{file.string()}));
    EXPECT_FALSE(unsaved(explorer.doc));
    EXPECT_EQ(title_name(explorer.doc), "explore_undo_saved.json");
    set_number(explorer, "m", 77);
    commit_edits(explorer);
    EXPECT_TRUE(unsaved(explorer.doc));
    EXPECT_EQ(title_name(explorer.doc), "explore_undo_saved.json * (unsaved edits)");
    ASSERT_TRUE(run(explorer, command::Undo{}));
    EXPECT_FALSE(unsaved(explorer.doc)) << "the scene is its file again";
    ASSERT_TRUE(run(explorer, command::Redo{}));
    EXPECT_TRUE(unsaved(explorer.doc));
    std::filesystem::remove(file);
}

// The status line tells only the last action: an edit
// after an undo clears "undid ..." (no stale "redid ... m" after a model switch).
TEST(ExploreUndo, AnEditClearsTheLastActionsStatus) {
    Explorer explorer;
    set_scene(explorer, default_scene(), "spec example");
    start_history(explorer);
    Material m = *selected_material(explorer);
    m.set_number("m", 40);
    run(explorer, command::SetMaterial{explorer.view.selected_object, m, ""});
    commit_edits(explorer);
    ASSERT_TRUE(run(explorer, command::Undo{}));
    EXPECT_NE(explorer.session.messages.status.find("undid"), std::string::npos);
    run(explorer, command::SetMaterial{explorer.view.selected_object, with_model_named(*selected_material(explorer), "metal"), ""});
    EXPECT_EQ(explorer.session.messages.status, "");
}

// Shift+drag on the display moves the selected object in
// the plane facing the camera so it follows the mouse (a drag across the
// display's height is the view's height at the object's depth: 2 d tan(fov/2)
// in perspective, the camera's height orthographic); a whole drag is one undo step.
TEST(ExploreUndo, ShiftDragMovesTheSelectedObjectInTheViewPlaneInOneStep) {
    Explorer explorer = started();
    Camera& c = explorer.doc.scene.camera;
    c.projection = Projection::perspective;
    c.position = {0, 0, 10};
    c.target = {0, 0, 0};
    c.up = {0, 1, 0};
    c.fov_y_deg = 30.0;
    explorer.doc.scene.objects[0].center = {0, 0, 0};
    commit_edits(explorer);
    const std::size_t steps = explorer.doc.history.undo_steps();
    const double shown_h = 320.0, per_unit = 2.0 * 10.0 * std::tan(15.0 * 3.14159265358979323846 / 180.0) / shown_h;
    for (int frame = 0; frame < 4; ++frame) run(explorer, command::MoveObjectInView{10.0, -5.0, shown_h});  // right and up
    EXPECT_NEAR(explorer.doc.scene.objects[0].center.x, 40.0 * per_unit, 1e-12);
    EXPECT_NEAR(explorer.doc.scene.objects[0].center.y, 20.0 * per_unit, 1e-12);
    EXPECT_NEAR(explorer.doc.scene.objects[0].center.z, 0.0, 1e-12) << "in the view plane";
    ASSERT_TRUE(commit_edits(explorer));
    EXPECT_EQ(explorer.doc.history.undo_steps(), steps + 1) << "one drag, one step";
    ASSERT_TRUE(run(explorer, command::Undo{}));
    EXPECT_EQ(explorer.doc.scene.objects[0].center, dvec3(0, 0, 0));
    explorer.doc.scene.camera.projection = Projection::orthographic;
    explorer.doc.scene.camera.height = 4.0;
    run(explorer, command::MoveObjectInView{shown_h, 0.0, shown_h});
    EXPECT_NEAR(explorer.doc.scene.objects[0].center.x, 4.0, 1e-12) << "orthographic: the camera's height";
}

}  // namespace
}  // namespace m3055::explore
