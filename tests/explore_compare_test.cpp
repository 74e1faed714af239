// The A/B compare's material B (explore/operations.h), without a window: A
// and B are edited independently, the split keeps B, only "B = copy of A"
// copies, and B's edits are undo steps of their own.
#include "explore_started.h"
#include "explore/files.h"
#include "explore/operations.h"
#include "io/message_text.h"
#include "models/model_spec.h"
#include "scene/load.h"
#include "scene/presets.h"

#include <gtest/gtest.h>

namespace m3055::explore {
namespace {

using test::run;
using test::started;

TEST(ExploreCompare, EditingADoesNotChangeB) {
    Explorer explorer = started();
    const Material b = explorer.doc.material_b;
    run(explorer, command::SetMaterial{explorer.view.selected_object, with_model_named(*selected_material(explorer), "metal"), ""});
    Material a = *selected_material(explorer);
    a.set_number("d", 0.25);
    run(explorer, command::SetMaterial{explorer.view.selected_object, a, ""});
    EXPECT_EQ(explorer.doc.material_b, b);
}

TEST(ExploreCompare, EditingBDoesNotChangeTheScene) {
    Explorer explorer = started();
    const nlohmann::json scene = scene_to_json(explorer.doc.scene, PathWriting::absolute());
    run(explorer, command::SetMaterial{kMaterialB, with_model_named(explorer.doc.material_b, "metal_blinn"), ""});
    Material b = explorer.doc.material_b;
    b.set_number("d", 0.3);
    run(explorer, command::SetMaterial{kMaterialB, b, ""});
    EXPECT_EQ(scene_to_json(explorer.doc.scene, PathWriting::absolute()), scene);
    EXPECT_EQ(explorer.doc.material_b.number("d"), 0.3);
    EXPECT_EQ(compare_scene(explorer).objects[0].material, explorer.doc.material_b) << "B's scene wears B";
}

TEST(ExploreCompare, SplitOnAndOffKeepsB) {
    Explorer explorer = started();
    run(explorer, command::SetMaterial{kMaterialB, with_model_named(explorer.doc.material_b, "metal_blinn"), ""});
    commit_edits(explorer);
    const Material b = explorer.doc.material_b;
    run(explorer, command::SetCompare{true});
    run(explorer, command::SetCompare{false});
    run(explorer, command::SetCompare{true});
    EXPECT_EQ(explorer.doc.material_b, b);
    EXPECT_FALSE(commit_edits(explorer)) << "the split is a view, no undo step";
}

// A B nobody has set is a copy of A when the split is
// first switched on (object 1 selected, a metal: not object 0's highlight).
TEST(ExploreCompare, SplitOnCopiesAIntoAnUntouchedB) {
    Explorer explorer = started();
    run(explorer, command::SetMaterial{explorer.view.selected_object, with_model_named(*selected_material(explorer), "metal"), ""});
    commit_edits(explorer);
    ASSERT_NE(explorer.doc.material_b, *selected_material(explorer));
    run(explorer, command::SetCompare{true});
    EXPECT_EQ(explorer.doc.material_b, *selected_material(explorer));
    EXPECT_TRUE(commit_edits(explorer));
    EXPECT_EQ(explorer.doc.history.undo_label(), "B = copy of A (split on)");
    run(explorer, command::SetCompare{false});
    run(explorer, command::SetMaterial{explorer.view.selected_object, with_model_named(*selected_material(explorer), "metal_blinn"), ""});
    run(explorer, command::SetCompare{true});
    EXPECT_EQ(explorer.doc.material_b.model().name, "metal_blinn") << "still untouched: A again";
    run(explorer, command::SetMaterial{kMaterialB, with_model_named(explorer.doc.material_b, "half_lambert"), ""});
    run(explorer, command::SetCompare{false});
    run(explorer, command::SetMaterial{explorer.view.selected_object, with_model_named(*selected_material(explorer), "metal"), ""});
    run(explorer, command::SetCompare{true});
    EXPECT_EQ(explorer.doc.material_b.model().name, "half_lambert") << "set by the user: kept";
}

TEST(ExploreCompare, OnlyCopyAToBCopiesAndItIsUndoable) {
    Explorer explorer = started();
    run(explorer, command::SetMaterial{explorer.view.selected_object, with_model_named(*selected_material(explorer), "metal"), ""});
    run(explorer, command::SetMaterial{kMaterialB, with_model_named(explorer.doc.material_b, "metal_blinn"), ""});
    commit_edits(explorer);
    run(explorer, command::CopyAToB{});
    commit_edits(explorer);
    EXPECT_EQ(explorer.doc.material_b, *selected_material(explorer));
    EXPECT_EQ(explorer.doc.history.undo_label(), "B = copy of A");
    ASSERT_TRUE(run(explorer, command::Undo{}));
    EXPECT_EQ(explorer.doc.material_b.model().name, "metal_blinn");
    EXPECT_EQ(selected_material(explorer)->model().name, "metal");
}

TEST(ExploreCompare, BsValueEditsAreNamedAfterB) {
    Explorer explorer = started();
    Material b = explorer.doc.material_b;
    const double m = b.number("m");
    b.set_number("m", 50);
    run(explorer, command::SetMaterial{kMaterialB, b, ""});
    commit_edits(explorer);
    EXPECT_EQ(explorer.doc.history.undo_label(), "B m " + text::format_number(m) + " -> 50");
}

TEST(ExploreCompare, FresnelPresetSplitsAPapersMetalIntoNormalAndFullEq19InOneUndoStep) {
    Explorer explorer = started();
    EXPECT_FALSE(run(explorer, command::CompareFresnel{})) << "the start scene's highlight is no metal";
    run(explorer, command::SetMaterial{explorer.view.selected_object, with_model_named(*selected_material(explorer), "metal_blinn"), ""});
    commit_edits(explorer);
    const Material before = *selected_material(explorer);
    const Material b_before = explorer.doc.material_b;
    ASSERT_TRUE(run(explorer, command::CompareFresnel{}));
    const Material& a = *selected_material(explorer);
    EXPECT_EQ(a.choice_name("conductor"), "gold");
    EXPECT_EQ(a.choice_name("fresnel"), "normal");
    EXPECT_EQ(explorer.doc.material_b.choice_name("conductor"), "gold");
    EXPECT_EQ(explorer.doc.material_b.choice_name("fresnel"), "full");
    EXPECT_TRUE(explorer.view.compare);
    commit_edits(explorer);
    EXPECT_EQ(explorer.doc.history.undo_label(), kFresnelPresetAction);
    ASSERT_TRUE(run(explorer, command::Undo{}));
    EXPECT_EQ(*selected_material(explorer), before);
    EXPECT_EQ(explorer.doc.material_b, b_before) << "A and B in the one step";
}

}  // namespace
}  // namespace m3055::explore
