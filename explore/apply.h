// Where commands take effect (explore/commands.h): one function applies a
// command, in the order they were given. The frame loop calls
// apply_commands once a frame, after the widgets, keys and script have
// given theirs; the page and --script, which want each command's outcome at
// once, call run_command.
#pragma once

#include "explore/explorer.h"

namespace m3055::explore {

// Applies one command: an edit of the document (named, undoable), an action
// on the view, the session or the files, or a read-out left in
// explorer.display_requests for the frame that draws the displays. Returns
// whether it did what was asked (false: not possible now, the reason in
// messages.error where the user should see it). Throws SceneError for a
// SetSceneValue the loader refuses.
bool apply_command(Explorer& explorer, const Command& command);

// Applies every command queued so far, in order (errors as apply_command's,
// a SceneError's message into messages.error).
void apply_commands(Explorer& explorer);

// Queues `command` behind those already given and applies them all now;
// returns `command`'s outcome (apply_command's; a SceneError propagates).
bool run_command(Explorer& explorer, Command command);

}  // namespace m3055::explore
