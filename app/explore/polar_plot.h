// A polar plot of a material's reflected value in the plane of incidence,
// drawn with ImGui's draw list: the lobe shape beside the sphere.
#pragma once

#include "scene/scene.h"

namespace m3055::explore {

// Plots, for view directions V from -90 to +90 degrees about the normal N, the
// colour the CPU reference (m3055::ref::shade_opaque) gives for `material` lit
// by `light` alone as a directional light at `incidence_deg` from N (on the
// left). One curve per channel. `size` is the plot's width in pixels.
void polar_plot(const Material& material, const Light& light, double incidence_deg, float size);

// The light's angle of incidence at the sphere point facing the camera
// (N = V = towards the camera): acos(N . L), in degrees.
double incidence_towards_camera(const Light& light, const Camera& camera);

}  // namespace m3055::explore
