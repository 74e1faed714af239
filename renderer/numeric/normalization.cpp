#include "numeric/normalization.h"

#include "numeric/angles.h"

#include <algorithm>
#include <cmath>

namespace m3055::numeric {

double gaussian_norm(double m) {
    const double upper = std::min(kPi / 2.0, 9.0 * m);
    const int n = 400;  // even; ~44 intervals per width m: error far below 1e-9
    const double h = upper / n;
    auto f = [m](double t) { return std::exp(-(t / m) * (t / m)) * std::cos(t) * std::sin(t); };
    double sum = f(0.0) + f(upper);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(i * h);
    return 1.0 / (2.0 * kPi * sum * h / 3.0);
}

}  // namespace m3055::numeric
