// The Objects panel's shape controls: a shape selector and the selected
// object's own fields (docs/shapes.md), and the conversion from one shape to
// another that both the selector and "+ add <shape>" use.
#pragma once

#include "scene/scene.h"

#include <optional>
#include <string>

namespace m3055::explore {

// "sphere", "plane", ... -> Shape; std::nullopt for anything else.
std::optional<Shape> parse_shape(const std::string& name);

// Turns `object` into `shape`, keeping its centre, material and rough size
// (a sphere of radius r becomes a cube of edge 1.6 r, a cylinder of radius r,
// ...); a plane becomes a floor under the object, 6 r wide.
void set_shape(Object& object, Shape shape);

// Shape selector and the fields of `object`'s shape, clamped to the loader's
// ranges so the scene stays valid. Returns true when something changed.
bool shape_editor(Object& object);

}  // namespace m3055::explore
