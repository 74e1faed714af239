// The screen rectangle a sphere can cover, so each sphere's quad shades only
// the pixels near its silhouette (10 000 full-screen quads would not be fast).
#pragma once

#include "passes/camera_frame.h"

#include <array>
#include <optional>

namespace m3055 {

// NDC rectangle {x0, y0, x1, y1}, padded by two pixels and clipped to the
// screen; std::nullopt when the sphere cannot be seen at all.
std::optional<std::array<float, 4>> sphere_ndc_rect(const CameraFrame& frame, const dvec3& center,
                                                    double radius);

}  // namespace m3055
