// Undo/redo of the document: steps of typed edits (explore/edit_values.h),
// each step what the user did between two moments when no widget or drag was
// in progress (a slider drag, a load, a preset), with the document's revision
// before and after it. Undoing applies the edits' values before, in reverse
// order; nothing is copied but the parts that changed. No ImGui, no GL.
#pragma once

#include "explore/edit_values.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace m3055::explore {

struct Step {
    std::vector<Edit> edits;  // in the order they were made
    std::string label;        // what the Edit menu says ("objects[0].material.m 10 -> 40")
    std::uint64_t revision_before = 0, revision_after = 0;
};

class History {
public:
    static constexpr std::size_t kMaxSteps = 500;

    // Forgets every step and the step in progress.
    void clear();

    // The step in progress (edits not committed yet).
    Step& pending() { return pending_; }
    const Step& pending() const { return pending_; }
    // Makes the step in progress an undo step and forgets the redo steps.
    // Returns whether there was one.
    bool commit();

    bool can_undo() const { return !undo_.empty(); }
    bool can_redo() const { return !redo_.empty(); }
    const std::string& undo_label() const { return undo_.back().label; }
    const std::string& redo_label() const { return redo_.back().label; }
    const Step& undo_step() const { return undo_.back(); }  // the step an undo would revert
    std::size_t undo_steps() const { return undo_.size(); }
    // Moves one step from the undo to the redo list (undo) or back (redo) and returns it.
    const Step& undo();
    const Step& redo();

private:
    Step pending_;
    std::deque<Step> undo_, redo_;
};

}  // namespace m3055::explore
