// The emitters of rect, disk and sky lights (docs/spec.md#75-area-lights-the-sky-and-shadows):
// their frames, areas and radiance, defined once for the loader, the GPU and
// the CPU reference, so that every renderer lights a point from the same emitter.
#pragma once

#include "scene/scene.h"

namespace m3055 {

// rect, disk and sky: lights with an extent, whose light at a point is an
// integral over the directions in which the point sees them.
bool is_area_light(LightType type);

// A rect's `up` when its file gives none: [0, 1, 0], or [0, 0, -1] when the
// unit `normal` is within 1 degree of +y or -y.
dvec3 default_rect_up(const dvec3& normal);

// A rect's unit axes: side1 along `up` made perpendicular to `normal` (the
// size[1] side), side0 = normal x side1 (the size[0] side), and its normal.
// The corners are position +- size[0]/2 side0 +- size[1]/2 side1.
struct RectFrame {
    dvec3 side0, side1, normal;
};
RectFrame rect_frame(const Light& light);

// The emitting area: size[0] size[1] for a rect, pi radius^2 for a disk.
double emitter_area(const Light& light);

// The radiance the light emits, a c / area for a rect or disk (a cosine
// emitter of intensity a c along its normal) and a c / pi for the sky.
dvec3 radiance(const Light& light);

}  // namespace m3055
