// The Objects panel's shape controls: a shape selector and the selected
// object's own fields (docs/shapes.md); the conversion is explore/shapes.h.
#pragma once

#include "explore/shapes.h"

namespace m3055::explore {

// Shape selector and the fields of `object`'s shape, clamped to the loader's
// ranges so the scene stays valid. Returns true when something changed.
bool shape_editor(Object& object);

}  // namespace m3055::explore
