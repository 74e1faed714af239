// OSMesa (off-screen Mesa) context: the fallback when EGL is missing or refuses 3.3 core.
#pragma once

#include "gl/context.h"

namespace m3055 {

// Returns nullptr and a one-phrase reason in `why` when OSMesa cannot give a 3.3 core context.
std::unique_ptr<HeadlessContext> create_osmesa_context(std::string* why);

}  // namespace m3055
