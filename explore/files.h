// The explorer's files: starting from a scene, loading a scene file or a
// figure preset (each one undo step), saving (the scene's own file, or Save
// As), and screenshots (the next free name; the PNG and its scene JSON).
// Errors go to the session's messages (a failed load also to load_error);
// the current scene stays.
#pragma once

#include "explore/commands.h"
#include "explore/explorer.h"
#include "frame/renderer.h"

#include <string>

namespace m3055::explore {

// Replaces the document with `scene` named `name`, its own file `file` ("":
// none; camera_home = its camera, selections reset, B = a copy of the first
// object's material): one undo step, named `action` ("load NAME" when empty).
// Returns the replaced document's name where it had unsaved edits (then
// Session::replaced_unsaved: quitting asks first), else "".
std::string set_scene(Explorer& explorer, const Scene& scene, const std::string& name, const std::string& action = "",
                      const std::string& file = "");
// "; the unsaved edits of NAME are one Ctrl+Z back" for a status line, or "".
std::string replaced_note(const std::string& replaced);

// A scene file; on failure the current scene stays and the loader's one-line
// message goes to messages.error and load_error. Returns success.
bool apply(Explorer& explorer, const command::LoadScene& c);
// The paper's figure presets (scenes/*.json embedded at build time), by file
// stem: "fig05" ... "fig13", "spec_example" (step "figure preset NAME"),
// named "preset NAME" in the title bar, with no file.
bool apply(Explorer& explorer, const command::LoadFigure& c);

// Writes the scene JSON (atomically); it becomes the scene's own file.
bool apply(Explorer& explorer, const command::SaveTo& c);
// Ctrl+S: to the scene's own file, or (none yet) asks for one (Save As).
bool apply(Explorer& explorer, const command::Save& c);
// Opens Save As with its field set to save_as_proposal.
bool apply(Explorer& explorer, const command::AskSaveAs& c);
// The Save As dialog's Save: an existing file other than the scene's own is
// written only when asked twice (the first time messages.error says so and
// false is returned).
bool apply(Explorer& explorer, const command::SaveAs& c);

// Save As's proposal: the scene's own file; without one, its name in the
// folder of the last file loaded or saved (a figure preset: "fig10.json"; the
// start of a practice: files.save_name, "submission.json") -- never the file
// of a scene it replaced, nor, for a preset, any file that exists (then
// NAME-2.json, -3, ...).
std::string save_as_proposal(const Explorer& explorer);
// F12: the next free DIR/NAME-0001.png (NAME: the scene file's stem, a
// preset's name, or "m3055"), neither it nor its .json existing yet.
std::string next_screenshot_path(const Explorer& explorer);
// Writes the screenshot (`path`, or the next free path) with `renderer`,
// which then shows the scene with its specialized program: exactly the PNG
// `m3055 render` writes for the JSON written beside it. `shows_render`: the
// renderer's display already holds those pixels (a refined display of area
// lights), written as they are rather than drawn again (seconds on llvmpipe).
// The full paths go to the status line, an error to messages.error.
// Returns whether the renderer's display holds the render's pixels of the
// scene afterwards (it does unless drawing them failed).
bool take_screenshot(Explorer& explorer, Renderer& renderer, const std::string& path, bool shows_render);

}  // namespace m3055::explore
