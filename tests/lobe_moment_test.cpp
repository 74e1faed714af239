// The closed form of a Phong lobe over a spherical polygon (reference/lobe_moment.h)
// against what it must equal: Lambert's formula for the cosine about N, the
// hemisphere's moments, and Gauss-Legendre quadrature over a rect and over the
// sky for sharp and wide lobes, odd and even exponents, the lobe's horizon
// across the emitter.
#include "reference/lobe_moment.h"

#include "reference/emitters.h"

#include "numeric/angles.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>

namespace m3055::ref {
namespace {

using numeric::kPi;

// Composite Gauss-Legendre (5 points on each of `panels` panels) of g over [a, b].
double gauss(const std::function<double(double)>& g, double a, double b, int panels) {
    static const double x[5] = {0.0, 0.5384693101056831, -0.5384693101056831, 0.9061798459386640,
                                -0.9061798459386640};
    static const double w[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891,
                                0.2369268850561891};
    const double h = (b - a) / panels;
    double sum = 0.0;
    for (int p = 0; p < panels; ++p)
        for (int i = 0; i < 5; ++i) sum += 0.5 * h * w[i] * g(a + h * (p + 0.5 + 0.5 * x[i]));
    return sum;
}

double lobe(const dvec3& u, const dvec3& N, const dvec3& axis, int n) {
    return glm::dot(N, u) > 0.0 && glm::dot(axis, u) > 0.0 ? std::pow(glm::dot(axis, u), n) : 0.0;
}

// The lobe over the rect c + s e0 + t e1 (s, t in [-1, 1]) seen from the origin, by its area.
double rect_by_quadrature(const dvec3& c, const dvec3& e0, const dvec3& e1, const dvec3& N, const dvec3& axis,
                          int n) {
    const dvec3 normal = glm::normalize(glm::cross(e0, e1));
    const double jacobian = glm::length(glm::cross(e0, e1));
    return gauss([&](double s) {
        return gauss([&](double t) {
            const dvec3 X = c + s * e0 + t * e1;
            const double d2 = glm::dot(X, X);
            const dvec3 u = X / std::sqrt(d2);
            return lobe(u, N, axis, n) * std::fabs(glm::dot(u, normal)) * jacobian / d2;
        }, -1.0, 1.0, 64);
    }, -1.0, 1.0, 64);
}

// The lobe over the hemisphere about +z, in latitude and longitude.
double hemisphere_by_quadrature(const dvec3& axis, int n) {
    const dvec3 up(0, 0, 1);
    return gauss([&](double theta) {
        return gauss([&](double phi) {
            const dvec3 u(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
            return lobe(u, up, axis, n) * std::sin(theta);
        }, 0.0, 2.0 * kPi, 128);
    }, 0.0, 0.5 * kPi, 64);
}

std::vector<dvec3> rect(const dvec3& c, const dvec3& e0, const dvec3& e1) {
    return {c - e0 - e1, c + e0 - e1, c + e0 + e1, c - e0 + e1};
}

TEST(LobeMoment, TheCosineAboutNIsLambertsFormulaForARectAcrossTheHorizon) {
    const dvec3 c(0.4, 0.3, 1.2), e0(0.9, 0.0, 0.3), e1(0.0, 0.8, -0.5);
    const dvec3 N = glm::normalize(dvec3(0.9, 0.2, 0.2));
    const std::vector<dvec3> corners = rect(c, e0, e1);
    // The horizon of N crosses the rect: clipping is part of what is checked.
    int above = 0;
    for (const dvec3& q : corners) above += glm::dot(q, N) > 0.0;
    ASSERT_GT(above, 0);
    ASSERT_LT(above, 4);
    std::vector<dvec3> above_horizon;  // Sutherland-Hodgman, as Lambert's formula wants it
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const dvec3 &a = corners[i], &b = corners[(i + 1) % corners.size()];
        const double ha = glm::dot(a, N), hb = glm::dot(b, N);
        if (ha >= 0.0) above_horizon.push_back(a);
        if ((ha >= 0.0) != (hb >= 0.0)) above_horizon.push_back(a + (ha / (ha - hb)) * (b - a));
    }
    EXPECT_NEAR(clipped_lobe_integral(corners, c, N, N, 1),
                polygon_projected_solid_angle(above_horizon, dvec3(0.0), N), 1e-12);
    // Either order of the corners.
    const std::vector<dvec3> reversed(corners.rbegin(), corners.rend());
    EXPECT_NEAR(clipped_lobe_integral(reversed, c, N, N, 1), clipped_lobe_integral(corners, c, N, N, 1), 1e-12);
}

TEST(LobeMoment, TheHemisphereHasItsKnownMoments) {
    const dvec3 up = glm::normalize(dvec3(0.2, 0.9, -0.3));
    for (int n : {1, 2, 3, 6, 15}) {
        // The integral of cos^n over the hemisphere about its pole: 2 pi / (n + 1).
        EXPECT_NEAR(clipped_lobe_integral(hemisphere_corners(up), up, up, up, n), 2.0 * kPi / (n + 1), 1e-12) << n;
    }
    // The sky's lune about N (what a Lambert surface sees of it): pi (1 + N.up) / 2.
    const dvec3 N = glm::normalize(dvec3(0.9, 0.1, 0.4));
    EXPECT_NEAR(clipped_lobe_integral(hemisphere_corners(up), up, N, N, 1), 0.5 * kPi * (1.0 + glm::dot(N, up)), 1e-12);
}

TEST(LobeMoment, AnOctantHasItsKnownMoments) {
    // Three hemispheres whose planes meet at right angles: an eighth of the sphere, pi / 2.
    const std::vector<dvec3> octant = {dvec3(1, 0, 0), dvec3(0, 1, 0), dvec3(0, 0, 1)};
    // x over it is the area of its shadow on the yz plane, a quarter of the unit disk;
    // x^2, y^2 and z^2 share the octant's solid angle alike.
    EXPECT_NEAR(lobe_integral_in_hemispheres(octant, octant[2], dvec3(1, 0, 0), 1), kPi / 4.0, 1e-12);
    EXPECT_NEAR(lobe_integral_in_hemispheres(octant, octant[2], dvec3(0, 1, 0), 2), kPi / 6.0, 1e-12);
    // The same plane twice is one boundary, not two; opposite planes leave no area.
    std::vector<dvec3> twice = octant;
    twice.push_back(octant[0]);
    EXPECT_NEAR(lobe_integral_in_hemispheres(twice, octant[2], dvec3(1, 0, 0), 1), kPi / 4.0, 1e-12);
    twice.back() = -octant[0];
    EXPECT_EQ(lobe_integral_in_hemispheres(twice, octant[2], dvec3(1, 0, 0), 1), 0.0);
}

TEST(LobeMoment, MatchesQuadratureOverARectWithTheLobesHorizonAcrossIt) {
    const dvec3 c(0.2, -0.1, 1.0), e0(0.7, 0.1, 0.2), e1(-0.1, 0.5, 0.1);
    const dvec3 N(0.0, 0.0, 1.0);
    for (const dvec3& towards : {dvec3(0.3, 0.0, 1.0), dvec3(1.0, 0.2, 0.3), dvec3(-0.4, 0.6, 0.2)}) {
        const dvec3 axis = glm::normalize(towards);
        for (int n : {3, 4, 5, 10, 20}) {
            const double expected = rect_by_quadrature(c, e0, e1, N, axis, n);
            EXPECT_NEAR(clipped_lobe_integral(rect(c, e0, e1), c, N, axis, n), expected, 1e-7 * std::max(1.0, expected))
                << "n " << n << ", axis " << axis.x << " " << axis.y << " " << axis.z;
        }
    }
}

TEST(LobeMoment, MatchesQuadratureOverTheSky) {
    const dvec3 up(0, 0, 1);
    for (const dvec3& towards : {dvec3(0.3, 0.1, 1.0), dvec3(1.0, 0.2, 0.05), dvec3(-0.4, 0.6, -0.3)}) {
        const dvec3 axis = glm::normalize(towards);
        for (int n : {3, 4, 5, 10, 20}) {
            const double expected = hemisphere_by_quadrature(axis, n);
            EXPECT_NEAR(clipped_lobe_integral(hemisphere_corners(up), up, up, axis, n), expected, 1e-7)
                << "n " << n << ", axis " << axis.x << " " << axis.y << " " << axis.z;
        }
    }
}

// The lobe over the disk c + rho (cos t e0 + sin t e1) (rho in [0, 1]) seen from the origin, by its area.
double disk_by_quadrature(const dvec3& c, const dvec3& e0, const dvec3& e1, const dvec3& N, const dvec3& axis,
                          int n) {
    const dvec3 normal = glm::normalize(glm::cross(e0, e1));
    const double jacobian = glm::length(glm::cross(e0, e1));
    return gauss([&](double rho) {
        return gauss([&](double t) {
            const dvec3 X = c + rho * (std::cos(t) * e0 + std::sin(t) * e1);
            const double d2 = glm::dot(X, X);
            const dvec3 u = X / std::sqrt(d2);
            return lobe(u, N, axis, n) * std::fabs(glm::dot(u, normal)) * jacobian * rho / d2;
        }, 0.0, 2.0 * kPi, 64);
    }, 0.0, 1.0, 64);
}

// A disk of radius r about c, tilted: its axes perpendicular to `facing`.
struct Disk {
    dvec3 c, e0, e1;
};
Disk disk(const dvec3& c, const dvec3& facing, double r) {
    const dvec3 n = glm::normalize(facing);
    const dvec3 a = glm::normalize(glm::cross(n, std::fabs(n.x) > 0.5 ? dvec3(0, 1, 0) : dvec3(1, 0, 0)));
    return {c, r * a, r * glm::cross(n, a)};
}

constexpr int kRimNodes = 24;  // glsl/common/lobe_moment.glsl: kDiskRimNodes

TEST(LobeMoment, MatchesQuadratureOverADisk) {
    const dvec3 N(0.0, 0.0, 1.0);
    for (const Disk& d : {disk(dvec3(0.2, -0.1, 1.0), dvec3(-0.2, 0.1, -1.0), 0.45),    // facing the point
                          disk(dvec3(-0.5, 0.3, 1.2), dvec3(0.3, -0.6, -0.5), 0.6),     // tilted, seen aslant
                          disk(dvec3(0.1, 0.05, 3.0), dvec3(0.0, 0.0, -1.0), 0.1)}) {   // small and far
        for (const dvec3& towards : {dvec3(0.3, 0.0, 1.0), d.c, dvec3(0.6, 0.3, 1.0)}) {
            const dvec3 axis = glm::normalize(towards);
            for (int n : {1, 2, 3, 4, 5, 10, 13, 20, 64}) {
                const double expected = disk_by_quadrature(d.c, d.e0, d.e1, N, axis, n);
                const std::optional<double> closed = disk_lobe_integral(d.c, d.e0, d.e1, N, axis, n, kRimNodes);
                ASSERT_TRUE(closed.has_value());
                // Relative to the lobe's whole integral where little of it falls on the disk.
                EXPECT_NEAR(*closed, expected, 1e-9 * std::max(expected, 2.0 * kPi / (n + 1)))
                    << "n " << n << ", axis " << axis.x << " " << axis.y << " " << axis.z;
            }
        }
    }
}

TEST(LobeMoment, TheCosineOverADiskOnItsAxisIsItsKnownProjectedSolidAngle) {
    // A disk of radius R facing the point from distance h on N: pi R^2 / (h^2 + R^2).
    const double R = 0.8, h = 1.3;
    const Disk d = disk(dvec3(0.0, 0.0, h), dvec3(0.0, 0.0, -1.0), R);
    const dvec3 N(0.0, 0.0, 1.0);
    EXPECT_NEAR(*disk_lobe_integral(d.c, d.e0, d.e1, N, N, 1, kRimNodes), kPi * R * R / (h * h + R * R), 1e-13);
}

TEST(LobeMoment, ADisksRimTurnedEitherWayGivesTheSameIntegral) {
    const Disk d = disk(dvec3(-0.5, 0.3, 1.2), dvec3(0.3, -0.6, -0.5), 0.6);
    const dvec3 N(0.0, 0.0, 1.0), axis = glm::normalize(dvec3(0.1, 0.2, 1.0));
    for (int n : {3, 4})
        EXPECT_NEAR(*disk_lobe_integral(d.c, d.e0, d.e1, N, axis, n, kRimNodes),
                    *disk_lobe_integral(d.c, d.e0, -d.e1, N, axis, n, kRimNodes), 1e-14);
}

TEST(LobeMoment, TheRimsTrapezoidRuleConvergesGeometrically) {
    const Disk d = disk(dvec3(0.2, -0.1, 1.0), dvec3(-0.2, 0.1, -1.0), 0.45);
    const dvec3 N(0.0, 0.0, 1.0), axis = glm::normalize(dvec3(0.6, 0.3, 1.0));
    const double expected = disk_by_quadrature(d.c, d.e0, d.e1, N, axis, 64);
    double previous = 1e300;
    for (int nodes : {8, 16, 24}) {
        const double error = std::fabs(*disk_lobe_integral(d.c, d.e0, d.e1, N, axis, 64, nodes) - expected) / expected;
        std::printf("%d nodes: relative error %.2e\n", nodes, error);
        EXPECT_LT(error, 1e-2 * previous) << nodes << " nodes";
        previous = error;
    }
    EXPECT_LT(previous, 1e-9) << "the shader's 24 nodes";
}

TEST(LobeMoment, ADiskAcrossAHorizonHasNoClosedFormHere) {
    const Disk d = disk(dvec3(1.0, 0.0, 0.2), dvec3(-1.0, 0.0, 0.0), 0.5);  // dips below z = 0
    const dvec3 N(0.0, 0.0, 1.0);
    EXPECT_FALSE(disk_lobe_integral(d.c, d.e0, d.e1, N, glm::normalize(d.c), 3, kRimNodes).has_value());
    const Disk above = disk(dvec3(0.0, 0.0, 1.0), dvec3(0.0, 0.0, -1.0), 0.5);
    EXPECT_FALSE(disk_lobe_integral(above.c, above.e0, above.e1, N, dvec3(1.0, 0.0, 0.0), 3, kRimNodes).has_value())
        << "the lobe's own horizon through the disk";
}

}  // namespace
}  // namespace m3055::ref
