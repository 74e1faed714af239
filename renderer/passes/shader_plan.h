// "Skip what a scene does not need": the #defines that specialize the sphere
// programs to one scene (models present, number and kinds of lights, whether
// any light carries its own lobes). Programs are cached by these defines, so a
// scene of the same shape reuses its program.
#pragma once

#include "scene/scene.h"

#include <string>
#include <vector>

namespace m3055 {

enum class ShaderMode {
    specialized,  // one program per scene shape (the default)
    general,      // one program for every scene: run-time branches and light loop
};

// Defines for the pass that draws `objects` (all opaque, or all translucent)
// under `lights` (only enabled lights with intensity > 0 count).
std::vector<std::string> specialization_defines(ShaderMode mode, const std::vector<const Object*>& objects,
                                                const std::vector<Light>& lights);

// HAS_AREA_LIGHTS and/or HAS_SHADOWS where `lights` (enabled, intensity > 0)
// have an area or sky light or a shadow: both modes add them, as programs
// without them are exactly the programs from before these lights.
std::vector<std::string> area_and_shadow_defines(const std::vector<Light>& lights);

}  // namespace m3055
