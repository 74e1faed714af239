// Normalizations that have no closed form, computed once per material on the
// CPU in double. Both the GPU material record (passes/material_buffer.cpp, via
// the model table's derived values) and the CPU reference use them, so the
// GPU path does not depend on the reference it is tested against.
#pragma once

namespace m3055::numeric {

// The normalization b of Torrance-Sparrow's Gaussian distribution
// D(h) = b exp(-(theta_h / m)^2), so that the integral of D (N.h) over the
// hemisphere is 1:
//   b = 1 / (2 pi integral_0^{pi/2} exp(-(t/m)^2) cos t sin t dt),
// by Simpson's rule over [0, min(pi/2, 9 m)] (exp(-81) is below 1e-35).
double gaussian_norm(double m);

}  // namespace m3055::numeric
