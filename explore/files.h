// The explorer's files: starting from a scene, loading a scene file or a
// figure preset (each one undo step), saving (the scene's own file, or Save
// As), and screenshots (the next free name; the PNG and its scene JSON). Errors go to state.error (and a
// failed load to state.load_error); the current scene stays.
#pragma once

#include "explore/state.h"
#include "frame/renderer.h"

#include <string>

namespace m3055::explore {

// Starts from `scene` (camera_home = its camera, selections reset, compare B =
// a copy of the first object's material): the undo step "load NAME".
void set_scene(ExplorerState& state, const Scene& scene, const std::string& name);

// Loads a JSON scene file; on failure keeps the current scene and puts the
// loader's one-line message into state.error. Returns success.
bool load_scene(ExplorerState& state, const std::string& path);

// The paper's figure presets (scenes/*.json embedded at build time), by file
// stem: "fig05" ... "fig13", "spec_example" (step "figure preset NAME").
// Unknown name -> error, false.
bool load_figure(ExplorerState& state, const std::string& name);

// Writes the scene JSON (atomically); it becomes the scene's own file. Errors go to state.error.
bool save_scene(ExplorerState& state, const std::string& path);
// Ctrl+S: to the scene's own file, or (none yet) asks for one (request_save_as).
void save_or_ask(ExplorerState& state);
// Save As's proposal: the scene's own file; without one, its name in the
// folder of the last file loaded or saved (a figure preset: "fig10.json"; the
// start of a practice: state.save_name, "submission.json") -- never the file
// of a scene it replaced.
std::string save_as_proposal(const ExplorerState& state);
// Opens Save As (save_as_requested) with the field set to save_as_proposal.
void request_save_as(ExplorerState& state);
// The Save As dialog's Save: an existing file other than the scene's own is
// written only when asked twice (the first time state.error says so and false
// is returned); then save_scene.
bool save_as(ExplorerState& state, const std::string& path);
// F12: the next free DIR/NAME-0001.png (NAME: the scene file's stem, or "m3055"),
// neither it nor its .json existing yet.
std::string next_screenshot_path(const ExplorerState& state);
// Writes the screenshot (state.screenshot_path once, else the next free
// path) with `renderer`, which then shows the scene with its specialized
// program: exactly the PNG `m3055 render` writes for the JSON written beside
// it. The full paths go to state.status, an error to state.error.
void take_screenshot(ExplorerState& state, Renderer& renderer);

}  // namespace m3055::explore
