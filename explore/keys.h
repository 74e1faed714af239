// Keyboard shortcuts: which key does what, given the state (a plain digit
// never replaces an edited scene) and what the UI says about the keyboard.
// Shared by the window (explore_ui/glfw_keys.h turns GLFW's codes into a
// KeyPress) and --script's `key`. No GLFW here.
#pragma once

#include "explore/explorer.h"

#include <optional>
#include <string>

namespace m3055::explore {

// The keys the explorer has shortcuts for; `other` for every other key.
enum class Key { other, escape, r, f1, f12, s, y, z, digit };

struct KeyPress {
    Key key = Key::other;
    int digit = -1;  // Key::digit: 0 ... 9 (main row or keypad)
    bool ctrl = false, alt = false, shift = false;
};

// What Dear ImGui says about the keyboard in this frame: shortcuts must not
// steal keys meant for a widget.
struct KeyFocus {
    bool text_input = false;      // io.WantTextInput: a text field is being typed into
    bool wants_keyboard = false;  // io.WantCaptureKeyboard: a widget (or dialog) takes keys
    bool item_active = false;     // ImGui::IsAnyItemActive(): a slider is held, a field edited
};

// Ctrl+Z undoes, Ctrl+Shift+Z and Ctrl+Y redo, Ctrl+S saves (to the scene's
// file, or asks), the platform's figure chord (Platform::figure_chord: Ctrl
// on the desktop, Ctrl+Alt in the page, whose Ctrl+digit is the browser's) with
// 0..9 loads a figure preset; single keys, only when no
// widget takes the keyboard: Esc quits (asking first when there are unsaved
// edits), R resets the camera, F1 toggles the panels, F12 takes a screenshot.
// A plain digit never loads anything, in any mode (a number typed with no
// field active must not replace the scene): it says in the status line that
// the chord with the digit loads Fig. 5-13 (1-9) or the spec example (0), undoably. None act
// while a text field is being typed into. The key's command goes on
// explorer.commands; returns true when it gave one.
bool handle_shortcut(Explorer& explorer, const KeyPress& press, const KeyFocus& focus = {});

// The figure preset a digit key loads: "spec_example" (0), "fig05" (1) ... "fig13" (9).
const char* figure_for_digit(int digit);

// How the figure chord is written in the UI: "Ctrl" or "Ctrl+Alt".
const char* figure_chord_name(FigureChord chord);

// "escape", "r", "f1", "f12", "ctrl+s", "ctrl+z", "ctrl+shift+z", "ctrl+y",
// "0".."9", "ctrl+0", "ctrl+alt+0" (any letter a-z) -> the key press; none for another name.
std::optional<KeyPress> parse_key_name(const std::string& name);

}  // namespace m3055::explore
