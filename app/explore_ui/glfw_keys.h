// GLFW's key codes and modifier bits -> the explorer's KeyPress (explore/keys.h).
#pragma once

#include "explore/keys.h"

namespace m3055::explore {

KeyPress key_press_from_glfw(int glfw_key, int glfw_mods);

}  // namespace m3055::explore
