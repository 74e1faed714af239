// The Lights panel's plot seen from above (app/explore_ui/light_plot.cpp),
// without ImGui: each emitter's outline in plan (x right, z down the plot),
// and a light turned about the vertical through the subject, an emitter's
// facing turned with it so it keeps facing the subject the same way.
#pragma once

#include "scene/scene.h"

#include <vector>

namespace m3055::explore {

// A point of the plan: scene x and z.
struct PlanPoint {
    double x = 0.0, z = 0.0;
};

// A rect's four corners or a disk's rim (`rim_points` points), relative to the
// light's position, seen from above; empty for other lights.
std::vector<PlanPoint> emitter_outline(const Light& light, int rim_points = 32);

// The light turned about the vertical through `subject` to `azimuth_deg`
// (scene/light_direction.h's azimuth): a directional light's direction, a
// positioned light's place (its height and distance kept); a rect's or
// disk's normal and up turned by the same angle.
void turn_to_azimuth(Light& light, const dvec3& subject, double azimuth_deg);

}  // namespace m3055::explore
