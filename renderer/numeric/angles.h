// pi and one degree in radians, in double, for the CPU side: the reference,
// shapes, cameras, light directions, the views of a BRDF. (The shaders have
// their own: glsl/common/constants.glsl.)
#pragma once

namespace m3055::numeric {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegree = kPi / 180.0;

}  // namespace m3055::numeric
