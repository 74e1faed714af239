// Keyboard shortcuts, shared by the GLFW key callback and --script's `key`.
#pragma once

#include "explore/state.h"

#include <string>

namespace m3055::explore {

// What Dear ImGui says about the keyboard in this frame: shortcuts must not
// steal keys meant for a widget.
struct KeyFocus {
    bool text_input = false;      // io.WantTextInput: a text field is being typed into
    bool wants_keyboard = false;  // io.WantCaptureKeyboard: a widget (or dialog) takes keys
    bool item_active = false;     // ImGui::IsAnyItemActive(): a slider is held, a field edited
};

// Ctrl+Z undoes, Ctrl+Shift+Z and Ctrl+Y redo, Ctrl+S saves (to the scene's
// file, or asks), Ctrl+0..9 load a figure preset; single keys, only when no
// widget takes the keyboard: Esc quits (asking first when there are unsaved
// edits), R resets the camera, F1 toggles the panels, F12 takes a screenshot,
// 1-9 load the figure presets Fig. 5-13 and 0 the spec example -- unless the
// scene has unsaved edits (a number typed with no field active must not
// replace the scene; Ctrl+digit does, undoably). None act while a text field
// is being typed into. Returns true when the key did something.
bool handle_shortcut(ExplorerState& state, int glfw_key, int glfw_mods, const KeyFocus& focus = {});

// "escape", "r", "f1", "f12", "ctrl+s", "ctrl+z", "ctrl+shift+z", "ctrl+y",
// "0".."9", "ctrl+0" -> GLFW key and modifiers.
bool parse_key_name(const std::string& name, int* glfw_key, int* glfw_mods);

}  // namespace m3055::explore
