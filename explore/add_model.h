// File > Add model... and a model file dropped on the window or the page: a
// Wavefront OBJ or glTF file becomes a mesh object (docs/shapes.md#meshes-from-files)
// standing on the floor, in view, selected, its file's materials by name in
// the Material panel; one undo step "add model NAME".
#pragma once

#include "explore/commands.h"
#include "explore/explorer.h"

#include <string>
#include <vector>

namespace m3055::explore {

// A path naming a model file (.obj, .gltf, .glb by its extension, any case).
bool is_model_path(const std::string& path);

// The height of the scene's floor: the lowest plane facing up or down, else y = 0.
double floor_height(const Scene& scene);

// `model` (a mesh with its model file loaded) sized to 0.4 of the view's
// height at the camera's target and standing on the floor: its bounding
// box's bottom on floor_height, on the floor's line through the target across
// the view, at the first place (the target, then alternately right and left)
// where its box overlaps no other object's box (a mesh's own, not rotated;
// else the box around its bounding sphere) and its middle is well inside the
// view; where none is, smaller (3/4, then 1/2); where still none is, the place
// in view that overlaps the others least.
Object placed_on_floor(const Scene& scene, Object model);

// What a file dropped on the window or the page asks: a .brdf opens on the
// selected object, a model file is added, anything else loads as a scene (a
// failure of either also shows in a dialog).
Command dropped_file_command(const std::string& path);
// Files dropped together, in order: each one's command, but a model's own
// files (.mtl, .bin) dropped with a model file give none (it reads them).
std::vector<Command> dropped_files_commands(const std::vector<std::string>& paths);

// Loads c.path (absolute in the object, so a save names it relative to the
// scene file) and inserts it placed_on_floor, selected. On failure one line
// naming the file goes to messages.error and load_error (and the load-error
// dialog for a drop), the scene unchanged, false.
bool apply(Explorer& explorer, const command::AddModel& c);

}  // namespace m3055::explore
