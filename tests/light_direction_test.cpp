// The lights panel's direction maths: azimuth/elevation and the sphere widget.
#include "scene/light_direction.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>

namespace m3055 {
namespace {

constexpr double kTol = 1e-12;

void expect_near(const dvec3& a, const dvec3& b, double tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(LightDirection, CardinalAngles) {
    expect_near(direction_from_angles({0, 0}), {0, 0, 1}, kTol);    // towards the viewer
    expect_near(direction_from_angles({90, 0}), {1, 0, 0}, kTol);   // right
    expect_near(direction_from_angles({-90, 0}), {-1, 0, 0}, kTol); // left
    expect_near(direction_from_angles({180, 0}), {0, 0, -1}, kTol); // behind
    expect_near(direction_from_angles({37, 90}), {0, 1, 0}, kTol);  // up, any azimuth
}

TEST(LightDirection, AnglesRoundTripOverTheSphere) {
    for (double a = -175.0; a <= 180.0; a += 17.5) {
        for (double e = -85.0; e <= 85.0; e += 8.5) {
            const dvec3 d = direction_from_angles({a, e});
            EXPECT_NEAR(glm::length(d), 1.0, kTol);
            const Angles back = angles_from_direction(d);
            EXPECT_NEAR(back.azimuth_deg, a, 1e-9) << a << " " << e;
            EXPECT_NEAR(back.elevation_deg, e, 1e-9) << a << " " << e;
        }
    }
}

TEST(LightDirection, SpecExampleDirectionIsUpperRightFront) {
    const Angles angles = angles_from_direction({1, 1, 1});
    EXPECT_NEAR(angles.azimuth_deg, 45.0, 1e-12);
    EXPECT_NEAR(angles.elevation_deg, std::asin(1.0 / std::sqrt(3.0)) * 180.0 / M_PI, 1e-12);
}

TEST(LightDirection, PoleKeepsThePreviousAzimuth) {
    EXPECT_EQ(angles_from_direction({0, 1, 0}, 33.0).azimuth_deg, 33.0);
    EXPECT_NEAR(angles_from_direction({0, -2, 0}, -12.0).elevation_deg, -90.0, kTol);
}

TEST(LightDirection, DiscCentreRimAndRing) {
    expect_near(direction_from_disc({0, 0}), {0, 0, 1}, kTol);        // centre: at the viewer
    expect_near(direction_from_disc({1, 0}), {1, 0, 0}, kTol);        // rim: side-on
    expect_near(direction_from_disc({0, 0.6}), {0, 0.6, 0.8}, kTol);  // front: z = sqrt(1 - r^2)
    // Half-way across the back ring: projected length 0.5, behind.
    expect_near(direction_from_disc({0, 1.0 + kBackRing / 2}), {0, 0.5, -std::sqrt(0.75)}, kTol);
    // Outer edge of the ring and beyond: straight behind.
    expect_near(direction_from_disc({-(1.0 + kBackRing), 0}), {0, 0, -1}, kTol);
    expect_near(direction_from_disc({5, 0}), {0, 0, -1}, kTol);
}

TEST(LightDirection, DiscIsContinuousAcrossTheRim) {
    const dvec3 inside = direction_from_disc({0.6 * (1 - 1e-10), 0.8 * (1 - 1e-10)});
    const dvec3 outside = direction_from_disc({0.6 * (1 + 1e-10), 0.8 * (1 + 1e-10)});
    EXPECT_LT(glm::length(inside - outside), 1e-3);
}

TEST(LightDirection, DiscRoundTripFrontAndBack) {
    for (double a = -170.0; a <= 180.0; a += 20.0) {
        for (double e = -80.0; e <= 80.0; e += 16.0) {
            const dvec3 d = direction_from_angles({a, e});
            const DiscPoint p = disc_from_direction(d);
            EXPECT_LE(std::hypot(p.x, p.y), 1.0 + kBackRing + 1e-12);
            expect_near(direction_from_disc(p), d, 1e-7);  // sqrt near the rim amplifies rounding
            EXPECT_EQ(std::hypot(p.x, p.y) <= 1.0, d.z >= 0.0) << a << " " << e;
        }
    }
}

TEST(LightDirection, DiscResultsAreUnitVectors) {
    for (double x = -2.0; x <= 2.0; x += 0.125) {
        for (double y = -2.0; y <= 2.0; y += 0.125) {
            EXPECT_NEAR(glm::length(direction_from_disc({x, y})), 1.0, 1e-12) << x << " " << y;
        }
    }
}

}  // namespace
}  // namespace m3055
