// No lost keystrokes: the window's key and character events wait in a queue
// and are handed to Dear ImGui a few at a time, so that within one frame no
// key changes state twice (Dear ImGui 1.86 keeps only a key's state at the
// frame's start: a press and release inside one frame would be lost) and no
// character follows a key press (a text field handles the frame's characters
// before its keys: "<BackSpace>a" would become "a<BackSpace>"). What 1.87's
// input queue does; the window (explore_ui/imgui_layer.cpp) feeds the
// events. No GLFW here: keys are the window's codes, as they come.
#pragma once

#include <cstddef>
#include <deque>

namespace m3055::explore {

struct InputEvent {
    enum class Kind { key, character };
    Kind kind = Kind::key;
    int key = 0, scancode = 0, action = 0, mods = 0;  // Kind::key: as the window reports them
    unsigned codepoint = 0;                           // Kind::character
    bool press = false;     // a press (not a release or a repeat)
    // A key a text field acts on (BackSpace, Delete, Enter, Tab, arrows, Home,
    // End; not a printable key nor a modifier): no character after its press in one frame.
    bool edit_key = false;
};

// How many events from the front of `queue` go to Dear ImGui this frame: all
// of them up to the first that would change a key fed this frame already, or
// that is a character after an edit key's press fed this frame. At
// least one when the queue is not empty.
std::size_t events_for_this_frame(const std::deque<InputEvent>& queue);

}  // namespace m3055::explore
