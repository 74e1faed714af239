// The explorer's logic, without a window: the document (what is edited,
// saved and undone), the view (how it is shown), the session (messages,
// files, watched .brdf files, the platform) and the queue of commands that
// change them. The frame loop (app/explore_ui/) and the page (app/web/) own
// one; unit tests make one (tests/explore_*_test.cpp). No ImGui, no GL.
#pragma once

#include "explore/commands.h"
#include "explore/document.h"
#include "explore/session.h"
#include "explore/view.h"

#include <vector>

namespace m3055::explore {

struct Explorer {
    Document doc;
    View view;
    Session session;
    CommandQueue commands;  // this frame's commands, applied in order by apply_commands
    std::vector<DisplayRequest> display_requests;  // read-outs waiting for the displays to be drawn
};

// The selected object's material (nullptr with no object): a mesh's from its
// model file, the selected one of them; clamps the selections.
Material* selected_material(Explorer& explorer);
// Which of the selected mesh's model-file materials the Material panel edits
// (an index into Object::groups), or -1 for an object with one material.
int selected_group(const Explorer& explorer);

// Quitting would lose work: the document has unsaved edits, or a load or a
// preset replaced one that had (Session::replaced_unsaved; undo brings it back).
bool work_unsaved(const Explorer& explorer);

// The second scene of the A/B compare: the same scene, the selected object wearing material B.
Scene compare_scene(const Explorer& explorer);

// Every model of the model table, in its order (the model selector's list).
std::vector<const ModelSpec*> all_models();

// A light's name as the scene format allows it (docs/spec.md#7-scene-files:
// 1 to 64 bytes of UTF-8 without control characters, or none): control
// characters dropped, cut to 64 bytes without splitting a character.
std::string valid_light_name(const std::string& typed);

}  // namespace m3055::explore
