#include "explore_ui/glfw_keys.h"

#include <GLFW/glfw3.h>

namespace m3055::explore {

KeyPress key_press_from_glfw(int key, int mods) {
    KeyPress press;
    press.ctrl = (mods & GLFW_MOD_CONTROL) != 0;
    press.alt = (mods & GLFW_MOD_ALT) != 0;
    press.shift = (mods & GLFW_MOD_SHIFT) != 0;
    if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) press.key = Key::digit, press.digit = key - GLFW_KEY_0;
    else if (key >= GLFW_KEY_KP_0 && key <= GLFW_KEY_KP_9) press.key = Key::digit, press.digit = key - GLFW_KEY_KP_0;
    else if (key == GLFW_KEY_ESCAPE) press.key = Key::escape;
    else if (key == GLFW_KEY_R) press.key = Key::r;
    else if (key == GLFW_KEY_F1) press.key = Key::f1;
    else if (key == GLFW_KEY_F12) press.key = Key::f12;
    else if (key == GLFW_KEY_S) press.key = Key::s;
    else if (key == GLFW_KEY_Y) press.key = Key::y;
    else if (key == GLFW_KEY_Z) press.key = Key::z;
    return press;
}

}  // namespace m3055::explore
