// No lost keystrokes: the window's key, character, mouse-button and pointer
// events wait in one queue and are handed to Dear ImGui a few at a time, so
// that within one frame no key or button changes state twice (Dear ImGui 1.86
// keeps only a key's state at the frame's start: a press and release inside
// one frame would be lost) and no character follows a key press (a text field
// handles the frame's characters before its keys: "<BackSpace>a" would become
// "a<BackSpace>"). Buttons share the queue so that a click keeps its place
// among the keys: a Ctrl+click is never seen as a plain click because the
// Ctrl press still waited behind earlier keys. The pointer's moves share it
// too, and a button's change and a move are never fed in one frame: a drag
// that arrived whole while a frame was busy (a shader compiling) is still a
// press, moves with the button held, and a release, not a click at its end.
// What 1.87's input queue does; the window (explore_ui/imgui_layer.cpp) feeds
// the events. No GLFW here: keys and buttons are the window's codes, as they come.
#pragma once

#include <cstddef>
#include <deque>

namespace m3055::explore {

struct InputEvent {
    enum class Kind { key, character, mouse_button, pointer };
    Kind kind = Kind::key;
    // Kind::key and Kind::mouse_button (key = the button): as the window reports them
    int key = 0, scancode = 0, action = 0, mods = 0;
    unsigned codepoint = 0;                           // Kind::character
    double x = 0, y = 0;  // Kind::mouse_button and Kind::pointer: the pointer then, in window coordinates
    bool press = false;     // a press (not a release or a repeat)
    // A key a text field acts on (BackSpace, Delete, Enter, Tab, arrows, Home,
    // End; not a printable key nor a modifier): no character after its press in one frame.
    bool edit_key = false;
    // Tab: its press moves the keyboard's focus to the next field, which takes
    // frames (ImGui focuses the next item a frame later, and a logarithmic
    // slider turns into its text field a frame or two after that): the
    // characters after it wait for them (kFocusFrames).
    bool focus_key = false;
};

// The frames a focus key's move takes before a character may follow it:
// a digit typed right after Tab on a slow frame (the sanitizer build's) went
// nowhere. Imperceptible as a delay (about 0.1 s at 30 frames a second).
inline constexpr int kFocusFrames = 3;

// How many events from the front of `queue` go to Dear ImGui this frame: all
// of them up to the first that would change a key or button fed this frame
// already, that is a character after an edit key's press fed this frame, or
// that is a button's change after a move or a move after a button's change
// fed this frame (moves in a row go together: the last one counts). At least
// one when the queue is not empty, unless `hold_characters` (a focus key's
// move under way): then none from the first character on.
std::size_t events_for_this_frame(const std::deque<InputEvent>& queue, bool hold_characters = false);

// The queue fed frame after frame (the window's ImGui layer): each frame's
// events_for_this_frame, the characters held for kFocusFrames frames after a
// focus key was fed.
class InputFeed {
public:
    // How many events from the front of `queue` go to Dear ImGui this frame;
    // the caller pops each and tells fed() about it.
    std::size_t this_frame(const std::deque<InputEvent>& queue) {
        const bool focus_moving = frames_since_focus_key_ < kFocusFrames;
        if (focus_moving) ++frames_since_focus_key_;
        return events_for_this_frame(queue, focus_moving);
    }
    void fed(const InputEvent& event) {
        if (event.focus_key) frames_since_focus_key_ = 0;
    }

private:
    int frames_since_focus_key_ = kFocusFrames;
};

}  // namespace m3055::explore
