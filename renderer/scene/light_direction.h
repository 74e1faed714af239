// Light direction maths for the explorer's lights panel, kept free of any UI
// code so it can be unit-tested: azimuth/elevation angles and the "drag on a
// small sphere" widget both map to the same unit vector (docs/spec.md#3-geometry: the vector
// from the surface towards the light).
//
// World frame as the default camera sees it (docs/spec.md#7-scene-files default camera at +z
// looking at the origin): +x right, +y up, +z towards the viewer.
//   azimuth   a: angle in the x-z plane, 0 = towards the viewer (+z),
//                +90 = right (+x), +-180 = behind the object (-z);
//   elevation e: angle above the x-z plane, +90 = straight up (+y).
//   direction = (cos e sin a, sin e, cos e cos a)
#pragma once

#include "scene/scene.h"

namespace m3055 {

struct Angles {
    double azimuth_deg = 0.0;    // (-180, 180]
    double elevation_deg = 0.0;  // [-90, 90]
};

// Unit direction for the given angles.
dvec3 direction_from_angles(const Angles& angles);

// Angles of a (not necessarily unit, non-zero) direction. At the poles the
// azimuth is undefined; `previous_azimuth_deg` is kept there so a slider does
// not jump when elevation passes +-90.
Angles angles_from_direction(const dvec3& direction, double previous_azimuth_deg = 0.0);

// The sphere widget: a disc of radius 1 shows the front hemisphere (z >= 0) as
// seen from the viewer; a ring around it, from radius 1 to 1 + kBackRing,
// shows the back hemisphere (z < 0), so back lights can be dragged too.
// Disc coordinates: x right, y UP (the widget flips screen y).
// Along a ray from the centre, radius r in [0, 1] is the front point whose
// projection has length r; r in [1, 1 + kBackRing] maps linearly back to the
// projected length 1 - (r - 1) / kBackRing on the back side. The two meet at
// the rim (z = 0), so dragging across it is continuous. Points beyond the ring
// are clamped onto its outer edge (straight behind, -z).
inline constexpr double kBackRing = 0.5;

struct DiscPoint {
    double x = 0.0;
    double y = 0.0;
};

dvec3 direction_from_disc(const DiscPoint& point);
DiscPoint disc_from_direction(const dvec3& direction);

}  // namespace m3055
