// EGL headless context (Mesa surfaceless platform, then EGL_EXT_platform_device).
#pragma once

#include "gl/context.h"

namespace m3055 {

// Returns nullptr and a one-phrase reason in `why` when EGL cannot give a 3.3 core context.
std::unique_ptr<HeadlessContext> create_egl_context(std::string* why);

}  // namespace m3055
