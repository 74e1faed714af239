// The lights panel's direction controls: a small sphere to drag the light on
// (front hemisphere inside the disc, back hemisphere in the ring around it;
// see scene/light_direction.h) and azimuth/elevation sliders. Both edit the
// same unit vector.
#pragma once

#include "scene/scene.h"

namespace m3055::explore {

// Returns true when the direction changed. `radius` is the front disc's radius in pixels.
bool light_sphere_widget(const char* id, dvec3* direction, float radius);

// Azimuth/elevation sliders; `azimuth_memory` keeps the azimuth at the poles.
bool light_angle_sliders(dvec3* direction, double* azimuth_memory);

}  // namespace m3055::explore
