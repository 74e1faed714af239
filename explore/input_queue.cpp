#include "explore/input_queue.h"

#include <set>

namespace m3055::explore {

std::size_t events_for_this_frame(const std::deque<InputEvent>& queue, bool hold_characters) {
    std::set<int> keys_fed, buttons_fed;
    bool key_pressed = false, moved = false;
    std::size_t n = 0;
    for (const InputEvent& event : queue) {
        if (event.kind == InputEvent::Kind::pointer) {
            if (!buttons_fed.empty()) break;  // a press is seen where it was before the pointer moves on
            moved = true;
        } else if (event.kind == InputEvent::Kind::mouse_button) {
            if (moved) break;  // the moves with the button as it was, then its change
            if (!buttons_fed.insert(event.key).second) break;  // a click's release: next frame
        } else if (event.kind == InputEvent::Kind::key) {
            if (!keys_fed.insert(event.key).second) break;  // its second transition: next frame
            if (event.press && event.edit_key) key_pressed = true;
        } else if (key_pressed || hold_characters) {
            break;  // a character after a key press: next frame, so the order holds
        }
        ++n;
    }
    const bool held = hold_characters && !queue.empty() && queue.front().kind == InputEvent::Kind::character;
    return n == 0 && !queue.empty() && !held ? 1 : n;
}

}  // namespace m3055::explore
