// A change of the document as a value: which part it changes and that part's
// value before and after (or, for a load, the whole document before and
// after). The one function that changes a document is record_edit: it
// applies the edit, names it, and adds it to the undo step in progress, so
// an edit costs what its part costs, whatever the size of the scene.
#pragma once

#include "explore/document.h"
#include "explore/edit_values.h"

#include <memory>
#include <string>

namespace m3055::explore {

// The document's content now, for a DocumentEdit's `before`.
std::shared_ptr<const DocumentContent> content_of(const Document& doc);

// Applies `edit` to `doc` and adds it to the undo step in progress: an edit
// of the same part as the step's last edit (a slider's next value) is merged
// into it, keeping the first value before, so a drag is one edit. An edit
// that changes nothing is dropped. Returns whether the document changed.
bool record_edit(Document& doc, Edit edit);

// Ends the undo step in progress (the frame loop calls it when no widget or
// drag is in progress). Returns whether there was one.
bool commit_edits(Document& doc);
// Moves one step back / forward (committing an edit in progress first).
// False when there is none.
bool undo(Document& doc);
bool redo(Document& doc);

// The step's name for the Edit menu and the status line.
std::string edit_label(const Edit& edit, const Scene& scene);

// Applies an edit's value after (forward) or before (backward) to `doc`'s content.
void apply_edit(Document& doc, const Edit& edit, bool forward);

}  // namespace m3055::explore
