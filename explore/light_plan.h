// The Lights panel's plot seen from above (app/explore_ui/light_plot.cpp),
// without ImGui: each emitter's outline in plan (x right, z down the plot),
// and a light turned about the vertical through the subject, an emitter's
// facing turned with it so it keeps facing the subject the same way.
#pragma once

#include "analysis/lighting_ratio.h"
#include "scene/scene.h"

#include <cstdint>
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

// What the plot reads off one revision of the document, found again only when
// the revision changes (a frame must not average every object, and a disk
// light's irradiance is a quadrature of about 25 ms): the subject's centre and
// the key-to-fill ratio there (renderer/analysis/lighting_ratio.h).
struct LightPlanReadouts {
    std::uint64_t revision = ~std::uint64_t(0);
    dvec3 subject{0.0};
    KeyFillRatio ratio;
};

// `readouts` brought up to `scene` at `revision`.
const LightPlanReadouts& update_light_plan(LightPlanReadouts& readouts, const Scene& scene, std::uint64_t revision);

}  // namespace m3055::explore
