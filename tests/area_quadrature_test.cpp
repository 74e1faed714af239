// The adaptive quadrature engine (reference/area_quadrature.h) on integrals
// whose values are known: a smooth one to its tolerance, a peak narrower than
// its first nodes found through the probe, shadows' edges straight and curved
// to the shadow tolerance, and the cell budget kept.
#include "reference/area_quadrature.h"

#include "numeric/angles.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace m3055::ref {
namespace {

using numeric::kPi;

// A patch of directions close to +z that carries the plane point (x, y) in
// [0, 1]^2 as the direction normalize(k (x - 1/2), k (y - 1/2), 1), with
// solid angle density 1: integrals over it are plain integrals over the square.
constexpr double kSpread = 0.01;
const Patch kSquare = [](double u, double v) {
    return PatchSample{glm::normalize(dvec3(kSpread * (u - 0.5), kSpread * (v - 0.5), 1.0)), 1.0, 1.0};
};

double x_of(const dvec3& w) { return w.x / w.z / kSpread + 0.5; }
double y_of(const dvec3& w) { return w.y / w.z / kSpread + 0.5; }

// The integrand sum f(x, y) dA over the nodes, in the first channel.
template <typename F>
AreaIntegrand integrand_of(F f) {
    AreaIntegrand integrand;
    integrand.value = [f](const std::vector<QuadratureNode>& nodes) {
        Shade6 s{};
        for (const QuadratureNode& node : nodes) s[0] += f(x_of(node.direction), y_of(node.direction)) * node.solid_angle;
        return s;
    };
    return integrand;
}

template <typename F>
double integral(F f, const AreaIntegrand& integrand, const AreaQuadrature& options, AreaStats* stats = nullptr) {
    double sum = 0.0;
    for (const QuadratureNode& node : integrate_area({kSquare}, integrand, options, stats))
        sum += f(x_of(node.direction), y_of(node.direction)) * node.solid_angle;
    return sum;
}

TEST(AreaQuadrature, ASmoothIntegralReachesItsTolerance) {
    const auto f = [](double x, double y) { return std::exp(3 * x + 2 * y) * std::cos(4 * y); };
    // (e^3 - 1)/3 times the integral of e^{2y} cos 4y over [0, 1].
    const double exact = (std::exp(3.0) - 1) / 3 * (std::exp(2.0) * (2 * std::cos(4.0) + 4 * std::sin(4.0)) - 2) / 20;
    for (const double tolerance : {1e-4, 1e-6, 1e-8}) {
        AreaQuadrature options;
        options.tolerance = tolerance;
        AreaStats stats;
        const double got = integral(f, integrand_of(f), options, &stats);
        EXPECT_LE(std::fabs(got - exact), tolerance * std::max(1.0, std::fabs(exact))) << tolerance;
        EXPECT_EQ(stats.unconverged, 0);
    }
}

TEST(AreaQuadrature, APeakBetweenTheFirstNodesIsFoundAtItsDirection) {
    // A Gaussian of width 1e-4 at (0.61, 0.37): far narrower than the first cells' nodes' spacing.
    const double sigma = 1e-4, x0 = 0.61, y0 = 0.37;
    const auto f = [&](double x, double y) {
        return std::exp(-((x - x0) * (x - x0) + (y - y0) * (y - y0)) / (2 * sigma * sigma)) / (2 * kPi * sigma * sigma);
    };
    AreaIntegrand integrand = integrand_of(f);
    AreaQuadrature options;
    EXPECT_LT(integral(f, integrand, options), 1e-3) << "without the probe the peak is not seen";
    integrand.peak = kSquare(x0, y0).direction;
    EXPECT_NEAR(integral(f, integrand, options), 1.0, 1e-5);
}

// Only the part of the square where `lit` holds is seen.
template <typename F, typename Lit>
double shadowed(F f, Lit lit, double tolerance, AreaStats* stats = nullptr) {
    AreaIntegrand integrand = integrand_of(f);
    integrand.visible = [lit](const QuadratureNode& node) { return lit(x_of(node.direction), y_of(node.direction)); };
    AreaQuadrature options;
    options.shadow_tolerance = tolerance;
    options.max_cells = 1 << 20;
    return integral(f, integrand, options, stats);
}

TEST(AreaQuadrature, AStraightShadowEdgeIsIntegratedToTheShadowTolerance) {
    // f = 1 + x y over the part of the square above the line y = 0.2 + 0.53 x.
    const auto f = [](double x, double y) { return 1 + x * y; };
    const auto lit = [](double x, double y) { return y > 0.2 + 0.53 * x; };
    // The integral of 1 + x y over y in [a + b x, 1], x in [0, 1], a = 0.2, b = 0.53.
    const double a = 0.2, b = 0.53;
    const double exact = (1 - a - b / 2) + 0.25 - (a * a / 4 + 2 * a * b / 6 + b * b / 8);
    for (const double tolerance : {1e-3, 1e-4, 1e-5}) {
        AreaStats stats;
        EXPECT_LE(std::fabs(shadowed(f, lit, tolerance, &stats) - exact), tolerance) << tolerance;
        EXPECT_EQ(stats.unconverged, 0);
    }
}

TEST(AreaQuadrature, ACurvedShadowConvergesAsTheSquareOfTheCells) {
    // The disk of radius 0.3 at (0.45, 0.55) in shadow: 1 - 0.09 pi of the unit square is lit.
    const auto f = [](double, double) { return 1.0; };
    const auto lit = [](double x, double y) { return (x - 0.45) * (x - 0.45) + (y - 0.55) * (y - 0.55) > 0.09; };
    const double exact = 1 - 0.09 * kPi;
    long long cells_coarse = 0, cells_fine = 0;
    for (const double tolerance : {1e-3, 1e-4, 1e-5}) {
        AreaStats stats;
        EXPECT_LE(std::fabs(shadowed(f, lit, tolerance, &stats) - exact), 2 * tolerance) << tolerance;
        (tolerance == 1e-3 ? cells_coarse : cells_fine) = stats.cells;
    }
    // Second order: a hundred times the accuracy for about ten times the cells, not a hundred.
    EXPECT_LT(cells_fine, 30 * cells_coarse);
}

TEST(AreaQuadrature, ACellBudgetStopsTheRefinementAndSaysSo) {
    const auto f = [](double x, double y) { return std::sin(40 * x) * std::sin(40 * y) + 2; };
    AreaQuadrature options;
    options.tolerance = 1e-12;
    options.max_cells = 64;
    AreaStats stats;
    integral(f, integrand_of(f), options, &stats);
    EXPECT_LE(stats.cells, 64 + 3);  // the last split may pass it by three
    EXPECT_EQ(stats.unconverged, 1);
    EXPECT_GT(stats.worst_error, 1e-12);
}

}  // namespace
}  // namespace m3055::ref
