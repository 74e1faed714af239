// Keyboard shortcuts, shared by the GLFW key callback and --script's `key`.
#pragma once

#include "explore/state.h"

#include <string>

namespace m3055::explore {

// Esc quits, R resets the camera, F1 toggles the panels, F12 takes a
// screenshot, Ctrl+S saves the scene JSON, 1-9 load the figure presets
// Fig. 5-13, 0 the spec example. Returns true when the key did something.
bool handle_shortcut(ExplorerState& state, int glfw_key, int glfw_mods);

// "escape", "r", "f1", "f12", "ctrl+s", "0".."9" -> GLFW key and modifiers.
bool parse_key_name(const std::string& name, int* glfw_key, int* glfw_mods);

}  // namespace m3055::explore
