// The A/B compare's material B (explore/operations.h), without a window: A
// and B are edited independently, the split keeps B, only "B = copy of A"
// copies, and B's edits are undo steps of their own.
#include "explore_started.h"
#include "explore/files.h"
#include "explore/operations.h"
#include "explore/undo.h"
#include "io/message_text.h"
#include "models/model_spec.h"
#include "scene/load.h"
#include "scene/presets.h"

#include <gtest/gtest.h>

namespace m3055::explore {
namespace {

using test::started;

TEST(ExploreCompare, EditingADoesNotChangeB) {
    ExplorerState state = started();
    const Material b = state.material_b;
    set_model(state, "metal");
    Material a = *selected_material(state);
    a.set_number("d", 0.25);
    edit_material(state, a);
    EXPECT_EQ(state.material_b, b);
}

TEST(ExploreCompare, EditingBDoesNotChangeTheScene) {
    ExplorerState state = started();
    const nlohmann::json scene = scene_to_json(state.scene, PathWriting::absolute());
    set_model_b(state, "metal_blinn");
    Material b = state.material_b;
    b.set_number("d", 0.3);
    edit_material_b(state, b);
    EXPECT_EQ(scene_to_json(state.scene, PathWriting::absolute()), scene);
    EXPECT_EQ(state.material_b.number("d"), 0.3);
    EXPECT_EQ(compare_scene(state).objects[0].material, state.material_b) << "B's scene wears B";
}

TEST(ExploreCompare, SplitOnAndOffKeepsB) {
    ExplorerState state = started();
    set_model_b(state, "metal_blinn");
    commit_edits(state);
    const Material b = state.material_b;
    set_compare(state, true);
    set_compare(state, false);
    set_compare(state, true);
    EXPECT_EQ(state.material_b, b);
    EXPECT_FALSE(commit_edits(state)) << "the split is a view, no undo step";
}

// A B nobody has set is a copy of A when the split is
// first switched on (object 1 selected, a metal: not object 0's highlight).
TEST(ExploreCompare, SplitOnCopiesAIntoAnUntouchedB) {
    ExplorerState state = started();
    set_model(state, "metal");
    commit_edits(state);
    ASSERT_NE(state.material_b, *selected_material(state));
    set_compare(state, true);
    EXPECT_EQ(state.material_b, *selected_material(state));
    EXPECT_TRUE(commit_edits(state));
    EXPECT_EQ(state.history.undo_label(), "B = copy of A (split on)");
    set_compare(state, false);
    set_model(state, "metal_blinn");
    set_compare(state, true);
    EXPECT_EQ(state.material_b.model().name, "metal_blinn") << "still untouched: A again";
    set_model_b(state, "half_lambert");
    set_compare(state, false);
    set_model(state, "metal");
    set_compare(state, true);
    EXPECT_EQ(state.material_b.model().name, "half_lambert") << "set by the user: kept";
}

TEST(ExploreCompare, OnlyCopyAToBCopiesAndItIsUndoable) {
    ExplorerState state = started();
    set_model(state, "metal");
    set_model_b(state, "metal_blinn");
    commit_edits(state);
    copy_a_to_b(state);
    commit_edits(state);
    EXPECT_EQ(state.material_b, *selected_material(state));
    EXPECT_EQ(state.history.undo_label(), "B = copy of A");
    ASSERT_TRUE(undo(state));
    EXPECT_EQ(state.material_b.model().name, "metal_blinn");
    EXPECT_EQ(selected_material(state)->model().name, "metal");
}

TEST(ExploreCompare, BsValueEditsAreNamedAfterB) {
    ExplorerState state = started();
    Material b = state.material_b;
    const double m = b.number("m");
    b.set_number("m", 50);
    edit_material_b(state, b);
    commit_edits(state);
    EXPECT_EQ(state.history.undo_label(), "B m " + text::format_number(m) + " -> 50");
}

TEST(ExploreCompare, FresnelPresetSplitsAPapersMetalIntoNormalAndFullEq19InOneUndoStep) {
    ExplorerState state = started();
    EXPECT_FALSE(compare_fresnel(state)) << "the start scene's highlight is no metal";
    set_model(state, "metal_blinn");
    commit_edits(state);
    const Material before = *selected_material(state);
    const Material b_before = state.material_b;
    ASSERT_TRUE(compare_fresnel(state));
    const Material& a = *selected_material(state);
    EXPECT_EQ(a.choice_name("conductor"), "gold");
    EXPECT_EQ(a.choice_name("fresnel"), "normal");
    EXPECT_EQ(state.material_b.choice_name("conductor"), "gold");
    EXPECT_EQ(state.material_b.choice_name("fresnel"), "full");
    EXPECT_TRUE(state.compare);
    commit_edits(state);
    EXPECT_EQ(state.history.undo_label(), kFresnelPresetAction);
    ASSERT_TRUE(undo(state));
    EXPECT_EQ(*selected_material(state), before);
    EXPECT_EQ(state.material_b, b_before) << "A and B in the one step";
}

}  // namespace
}  // namespace m3055::explore
