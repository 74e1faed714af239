// The document's typed edits (explore/edits.h, explore/edit_label.h) and the
// command queue (explore/apply.h): a drag is one edit from its first value to
// its last, named from the typed values; "unsaved" follows revisions; the
// commands of a frame take effect in the order they were given.
#include "explore_started.h"
#include "explore/edit_label.h"
#include "explore/edits.h"
#include "explore/operations.h"

#include <gtest/gtest.h>

#include <string>

namespace m3055::explore {
namespace {

using test::run;
using test::started;

Material with_m(const Explorer& explorer, double m) {
    Material material = explorer.doc.scene.objects[0].material;
    material.set_number("m", m);
    return material;
}

TEST(ExploreEdits, LabelNumbersHaveThreeSignificantDigits) {
    EXPECT_EQ(label_number(1557.0678294090574), "1560");
    EXPECT_EQ(label_number(6.0), "6");
    EXPECT_EQ(label_number(251.0), "251");
    EXPECT_EQ(label_number(0.25), "0.25");
    EXPECT_EQ(label_number(0.123456), "0.123");
    EXPECT_EQ(label_number(-2.5), "-2.5");
    EXPECT_EQ(label_number(0.0), "0");
    EXPECT_EQ(label_number(-0.0), "0");
    EXPECT_EQ(label_number(0.00012345), "1.23e-04");
    EXPECT_EQ(label_number(2.5e7), "2.50e+07");
}

TEST(ExploreEdits, ADragOfManyTicksIsOneEditFromItsFirstValueToItsLast) {
    Explorer explorer = started();
    const double start = explorer.doc.scene.objects[0].material.number("m");
    for (int tick = 1; tick <= 30; ++tick)
        explorer.commands.push(command::SetMaterial{0, with_m(explorer, 10.0 + tick * 50.0), ""});
    apply_commands(explorer);
    ASSERT_EQ(explorer.doc.history.pending().edits.size(), 1u) << "merged into one edit";
    ASSERT_TRUE(commit_edits(explorer));
    EXPECT_EQ(explorer.doc.history.undo_label(), "objects[0].material.m " + label_number(start) + " -> 1510");
    ASSERT_TRUE(run(explorer, command::Undo{}));
    EXPECT_EQ(explorer.doc.scene.objects[0].material.number("m"), start);
}

TEST(ExploreEdits, ADragBackToWhereItStartedIsNoStepAndNothingUnsaved) {
    Explorer explorer = started();
    const double start = explorer.doc.scene.objects[0].material.number("m");
    run(explorer, command::SetMaterial{0, with_m(explorer, 99.0), ""});
    EXPECT_TRUE(unsaved(explorer.doc)) << "an edit in progress is unsaved at once";
    run(explorer, command::SetMaterial{0, with_m(explorer, start), ""});
    EXPECT_FALSE(commit_edits(explorer));
    EXPECT_FALSE(explorer.doc.history.can_undo());
    EXPECT_FALSE(unsaved(explorer.doc));
}

TEST(ExploreEdits, UnsavedFollowsRevisionsThroughUndoAndRedo) {
    Explorer explorer = started();
    run(explorer, command::SetMaterial{0, with_m(explorer, 40.0), ""});
    commit_edits(explorer);
    run(explorer, command::SetMaterial{0, with_m(explorer, 50.0), ""});
    commit_edits(explorer);
    EXPECT_TRUE(unsaved(explorer.doc));
    run(explorer, command::Undo{});
    run(explorer, command::Undo{});
    EXPECT_FALSE(unsaved(explorer.doc)) << "back at the start";
    run(explorer, command::Redo{});
    EXPECT_TRUE(unsaved(explorer.doc));
    run(explorer, command::SetMaterial{0, with_m(explorer, 60.0), ""});
    commit_edits(explorer);
    EXPECT_FALSE(explorer.doc.history.can_redo()) << "a new edit forgets the redo steps";
    run(explorer, command::Undo{});
    run(explorer, command::Undo{});
    EXPECT_FALSE(unsaved(explorer.doc));
}

TEST(ExploreEdits, AFramesCommandsTakeEffectInTheOrderGiven) {
    Explorer explorer = started();
    const double start = explorer.doc.scene.objects[0].material.number("m");
    explorer.commands.push(command::SetMaterial{0, with_m(explorer, 40.0), ""});
    explorer.commands.push(command::Undo{});  // undoes the edit given before it, in the same frame
    explorer.commands.push(command::AddObject{Shape::cube});
    apply_commands(explorer);
    EXPECT_EQ(explorer.doc.scene.objects[0].material.number("m"), start);
    ASSERT_EQ(explorer.doc.scene.objects.size(), 2u);
    EXPECT_EQ(explorer.doc.scene.objects[1].shape, Shape::cube);
    EXPECT_EQ(explorer.view.selected_object, 1);
    EXPECT_TRUE(explorer.commands.empty());
}

TEST(ExploreEdits, ReadOutsWaitForTheDisplaysInOrder) {
    Explorer explorer = started();
    explorer.session.render_needed = false;
    explorer.commands.push(DisplayRequest{command::Probe{3, 4}});
    explorer.commands.push(DisplayRequest{command::Screenshot{"shot.png"}});
    apply_commands(explorer);
    ASSERT_EQ(explorer.display_requests.size(), 2u);
    EXPECT_TRUE(std::holds_alternative<command::Probe>(explorer.display_requests[0]));
    EXPECT_TRUE(std::holds_alternative<command::Screenshot>(explorer.display_requests[1]));
    EXPECT_TRUE(explorer.session.render_needed) << "a frame draws the displays, then answers";
}

TEST(ExploreEdits, ObjectsAddedAndRemovedUndoInPlace) {
    Explorer explorer = started();
    run(explorer, command::AddObject{Shape::torus});
    run(explorer, command::AddObject{Shape::cylinder});
    commit_edits(explorer);
    run(explorer, command::RemoveObject{1});
    commit_edits(explorer);
    EXPECT_EQ(explorer.doc.history.undo_label(), "remove object 1");
    ASSERT_EQ(explorer.doc.scene.objects.size(), 2u);
    EXPECT_EQ(explorer.doc.scene.objects[1].shape, Shape::cylinder);
    ASSERT_TRUE(run(explorer, command::Undo{}));
    ASSERT_EQ(explorer.doc.scene.objects.size(), 3u);
    EXPECT_EQ(explorer.doc.scene.objects[1].shape, Shape::torus) << "back in its place";
    ASSERT_TRUE(run(explorer, command::Undo{}));
    EXPECT_EQ(explorer.doc.scene.objects.size(), 1u) << "both additions were one step";
}

TEST(ExploreEdits, FieldsAreNamedByTheirSceneFileKeys) {
    Light before, after;
    before.name = "fill";
    after = before;
    after.intensity = 0.3;
    EXPECT_EQ(light_change(before, after, 1).label(), "light fill intensity 1 -> 0.3");
    after = before;
    after.name = "";
    after.direction = {1, 0, 0};
    EXPECT_EQ(light_change(before, after, 2).label(), "rename light 2") << "a name removed";
    after.name = "key";
    EXPECT_EQ(light_change(before, after, 2).label(), "rename light fill -> key");
    Light rect = before;
    rect.type = LightType::rect;
    Light wider = rect;
    wider.size[0] = 2.5;
    EXPECT_EQ(light_change(rect, wider, 1).label(), "light fill size[0] 1 -> 2.5");
    Light shadowed = rect;
    shadowed.shadow = true;
    EXPECT_FALSE(light_change(rect, shadowed, 1).empty()) << "an area light's edits are edits";
    Light turned = rect;
    turned.normal = {0, -1, 0};
    EXPECT_FALSE(light_change(rect, turned, 1).empty());
    Object plane;
    plane.shape = Shape::plane;
    Object tilted = plane;
    tilted.axis = {0, 0, 1};
    EXPECT_EQ(object_change(plane, tilted, 3).label(), "objects[3].normal");
    Camera camera, moved = camera;
    moved.fov_y_deg = 45;
    EXPECT_EQ(camera_change(camera, moved).label(), "camera.fov_y_deg 30 -> 45");
    Material metal = Material::of("metal"), rougher = metal;
    rougher.set_lobes({{0.5, 0.3}});
    EXPECT_EQ(material_change(metal, rougher).what, "lobes");
}

}  // namespace
}  // namespace m3055::explore
