// The shapes an object can take in the explorer: their names, and the
// conversion from one shape to another that the Objects panel's selector,
// "+ add <shape>" and the script's `shape` all use.
#pragma once

#include "scene/scene.h"

#include <optional>
#include <string>

namespace m3055::explore {

// Every shape, in the Objects panel's order.
inline constexpr Shape kAllShapes[] = {Shape::sphere, Shape::plane, Shape::cube, Shape::cylinder, Shape::torus};

// "sphere", "plane", ... -> Shape; std::nullopt for anything else.
std::optional<Shape> parse_shape(const std::string& name);

// Turns `object` into `shape`, keeping its centre, material and rough size
// (a sphere of radius r becomes a cube of edge 1.6 r, a cylinder of radius r,
// ...); a plane becomes a floor under the object, 6 r wide.
void set_shape(Object& object, Shape shape);

}  // namespace m3055::explore
