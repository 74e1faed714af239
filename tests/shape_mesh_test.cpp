// The meshes of renderer/geometry/ against the analytic shapes they stand for:
// winding and normals point outward, vertices lie on the surface with its
// exact normal, points inside triangles stay within the stated tessellation
// bounds, and the shading error of the default tessellation (docs/shapes.md)
// measured by ray-casting the mesh and the analytic surface along the same rays.
#include "geometry/mesh.h"
#include "reference/mesh_hits.h"
#include "reference/reference.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>

namespace m3055 {
namespace {

using geometry::Mesh;

constexpr double kPi = 3.14159265358979323846;

// ---- the analytic shapes: closest surface point's normal and signed distance ----

struct Analytic {
    std::function<double(const dvec3&)> distance;  // signed distance to the surface (> 0 outside)
    std::function<dvec3(const dvec3&)> normal;     // unit outward normal of the closest surface point
};

Analytic cylinder_side(const dvec3& c, const dvec3& axis, double radius) {
    auto radial = [=](const dvec3& p) {
        const dvec3 q = p - c;
        return q - glm::dot(q, axis) * axis;
    };
    return {[=](const dvec3& p) { return glm::length(radial(p)) - radius; },
            [=](const dvec3& p) { return glm::normalize(radial(p)); }};
}

Analytic torus(const dvec3& c, const dvec3& axis, double major, double minor) {
    auto ring = [=](const dvec3& p) {  // closest point of the tube's centre circle
        const dvec3 q = p - c;
        return c + major * glm::normalize(q - glm::dot(q, axis) * axis);
    };
    return {[=](const dvec3& p) { return glm::length(p - ring(p)) - minor; },
            [=](const dvec3& p) { return glm::normalize(p - ring(p)); }};
}

// Over barycentric samples of every triangle: the largest distance to the
// analytic surface and the largest angle between the interpolated normal and
// the analytic one.
struct MeshError {
    double distance = 0, angle = 0;
};

MeshError measure(const Mesh& mesh, const Analytic& shape, const std::function<bool(int part)>& use) {
    MeshError error;
    constexpr int kSteps = 6;
    for (std::size_t t = 0; t < mesh.triangles(); ++t) {
        if (!use(mesh.parts[t])) continue;
        const std::uint32_t* i = &mesh.indices[3 * t];
        for (int a = 0; a <= kSteps; ++a) {
            for (int b = 0; a + b <= kSteps; ++b) {
                const double u = double(a) / kSteps, v = double(b) / kSteps, w = 1 - u - v;
                const dvec3 p = w * mesh.positions[i[0]] + u * mesh.positions[i[1]] + v * mesh.positions[i[2]];
                const dvec3 n = glm::normalize(w * mesh.normals[i[0]] + u * mesh.normals[i[1]] + v * mesh.normals[i[2]]);
                error.distance = std::max(error.distance, std::abs(shape.distance(p)));
                error.angle = std::max(error.angle, std::acos(std::clamp(glm::dot(n, shape.normal(p)), -1.0, 1.0)));
            }
        }
    }
    return error;
}

// Every triangle's winding agrees with its vertex normals and points away from `inside(p)`.
void expect_outward(const Mesh& mesh, const std::function<dvec3(const dvec3& centroid)>& inside) {
    ASSERT_EQ(mesh.parts.size(), mesh.triangles());
    for (std::size_t t = 0; t < mesh.triangles(); ++t) {
        const std::uint32_t* i = &mesh.indices[3 * t];
        const dvec3 a = mesh.positions[i[0]], b = mesh.positions[i[1]], c = mesh.positions[i[2]];
        const dvec3 geometric = glm::normalize(glm::cross(b - a, c - a));
        const dvec3 centroid = (a + b + c) / 3.0;
        EXPECT_GT(glm::dot(geometric, centroid - inside(centroid)), 0.0) << "triangle " << t;
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(glm::length(mesh.normals[i[k]]), 1.0, 1e-12);
            // Smooth normals lean at most half a segment from the facet's own normal.
            EXPECT_GT(glm::dot(geometric, mesh.normals[i[k]]), 0.9) << "triangle " << t;
        }
    }
}

TEST(ShapeMesh, AxisFrameIsOrthonormalAndRightHanded) {
    for (const dvec3& axis : {dvec3(0, 1, 0), dvec3(1, 0, 0), dvec3(0, 0, -1), glm::normalize(dvec3(1, 1, 1)),
                              glm::normalize(dvec3(-0.3, 0.2, 5.0)), glm::normalize(dvec3(1e-9, 1, 0))}) {
        const geometry::AxisFrame f = geometry::axis_frame(axis);
        EXPECT_NEAR(glm::length(f.t), 1.0, 1e-15);
        EXPECT_NEAR(glm::length(f.b), 1.0, 1e-15);
        EXPECT_NEAR(glm::dot(f.t, f.a), 0.0, 1e-15);
        EXPECT_NEAR(glm::dot(f.b, f.a), 0.0, 1e-15);
        EXPECT_NEAR(glm::length(glm::cross(f.t, f.b) - f.a), 0.0, 1e-15);
    }
    // The floor's frame: T = x, B = y x x = -z.
    const geometry::AxisFrame floor = geometry::axis_frame({0, 1, 0});
    EXPECT_EQ(floor.t, dvec3(1, 0, 0));
    EXPECT_EQ(floor.b, dvec3(0, 0, -1));
}

TEST(ShapeMesh, PlaneIsASquareFacingItsNormal) {
    const dvec3 n = glm::normalize(dvec3(0.2, 1, -0.1)), c(1, -2, 3);
    const Mesh mesh = geometry::make_plane(c, n, 4.0);
    ASSERT_EQ(mesh.triangles(), 2u);
    for (const dvec3& p : mesh.positions) {
        EXPECT_NEAR(glm::dot(p - c, n), 0.0, 1e-14);
        EXPECT_NEAR(glm::length(p - c), 4.0 * std::sqrt(0.5), 1e-14);
    }
    for (const dvec3& normal : mesh.normals) EXPECT_EQ(normal, n);
    expect_outward(mesh, [&](const dvec3& p) { return p - n; });
}

TEST(ShapeMesh, CubeHasSixFlatOutwardFacesAtHalfTheSize) {
    const dvec3 c(0.5, 1, -1), rotation(20, -35, 50);
    const Mesh mesh = geometry::make_cube(c, 2.0, rotation);
    ASSERT_EQ(mesh.triangles(), 12u);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        EXPECT_NEAR(glm::length(mesh.positions[v] - c), std::sqrt(3.0), 1e-13);  // corners
        EXPECT_NEAR(glm::dot(mesh.positions[v] - c, mesh.normals[v]), 1.0, 1e-13);  // on its face
    }
    for (int face = 0; face < 6; ++face) {
        const dvec3 axis = face % 3 == 0 ? dvec3(1, 0, 0) : face % 3 == 1 ? dvec3(0, 1, 0) : dvec3(0, 0, 1);
        const dvec3 expected = geometry::rotate_xyz((face < 3 ? 1.0 : -1.0) * axis, rotation);
        EXPECT_NEAR(glm::length(mesh.normals[4 * face] - expected), 0.0, 1e-15);
        EXPECT_EQ(mesh.parts[2 * face], face);
    }
    expect_outward(mesh, [&](const dvec3&) { return c; });
}

// The rotation is about x, then y, then z: (1, 0, 0) turned 90 degrees about y is (0, 0, -1).
TEST(ShapeMesh, RotationOrderIsXThenYThenZ) {
    const dvec3 p = geometry::rotate_xyz({1, 0, 0}, {0, 90, 0});
    EXPECT_NEAR(glm::length(p - dvec3(0, 0, -1)), 0.0, 1e-15);
    const dvec3 q = geometry::rotate_xyz({0, 1, 0}, {90, 0, 90});  // y -> z (about x), z stays (about z)
    EXPECT_NEAR(glm::length(q - dvec3(0, 0, 1)), 0.0, 1e-15);
}

TEST(ShapeMesh, CylinderVerticesAndSideWithinTheSagitta) {
    const dvec3 c(0, 0.5, 0), axis = glm::normalize(dvec3(0.3, 1, 0.2));
    for (int segments : {8, 64}) {
        const Mesh mesh = geometry::make_cylinder(c, axis, 0.6, 1.4, true, segments);
        EXPECT_EQ(mesh.triangles(), triangle_count([&] {
                      Object o;
                      o.shape = Shape::cylinder, o.segments = segments;
                      return o;
                  }()));
        // Side: exactly on the surface at the vertices; between them within the
        // sagitta r (1 - cos(pi / segments)); the interpolated normal is the
        // exact radial direction of the interpolated point (error ~ 0).
        const MeshError side = measure(mesh, cylinder_side(c, axis, 0.6), [](int part) { return part == 0; });
        EXPECT_LE(side.distance, 0.6 * (1 - std::cos(kPi / segments)) * (1 + 1e-9));
        EXPECT_LE(side.angle, 1e-7);
        // Caps: on their planes, with the axis normal.
        for (std::size_t t = 0; t < mesh.triangles(); ++t) {
            if (mesh.parts[t] == 0) continue;
            const dvec3 n = mesh.parts[t] == 2 ? axis : -axis;
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = mesh.indices[3 * t + k];
                EXPECT_NEAR(glm::dot(mesh.positions[v] - c, n), 0.7, 1e-13);
                EXPECT_NEAR(glm::length(mesh.normals[v] - n), 0.0, 1e-15);
            }
        }
        expect_outward(mesh, [&](const dvec3& p) {
            const double h = glm::dot(p - c, axis);
            return std::abs(std::abs(h) - 0.7) < 1e-9 ? c : c + h * axis;  // caps: the centre; side: the axis
        });
    }
}

TEST(ShapeMesh, TorusWithinTheStatedBounds) {
    const dvec3 c(0, 0, 0), axis = glm::normalize(dvec3(0.2, 1, 0.5));
    const double major = 1.0, minor = 0.3;
    for (int segments : {16, 64, 128}) {
        const Mesh mesh = geometry::make_torus(c, axis, major, minor, segments);
        const MeshError error = measure(mesh, torus(c, axis, major, minor), [](int) { return true; });
        // Positions: within the sagitta of the outer circle, (R + r)(1 - cos(pi/N)),
        // plus that of the tube, r (1 - cos(pi/N)). Normals: within that distance
        // over the tube's radius (radians).
        const double sagitta = (major + 2 * minor) * (1 - std::cos(kPi / segments));
        std::printf("torus %3d segments: max distance %.3g (bound %.3g), max normal angle %.3g rad (bound %.3g)\n",
                    segments, error.distance, sagitta, error.angle, sagitta / minor);
        EXPECT_LE(error.distance, sagitta);
        EXPECT_LE(error.angle, sagitta / minor);
        expect_outward(mesh, [&](const dvec3& p) {
            const dvec3 q = p - c;
            return c + major * glm::normalize(q - glm::dot(q, axis) * axis);  // the tube's centre circle
        });
    }
}

// ---- the shading error of a tessellation: mesh against the analytic surface ----

// Nearest hit of the analytic surface along `ray`, found by Newton's method on
// the signed distance from the mesh's own hit (which lies within the sagitta).
std::optional<double> refine_hit(const Analytic& shape, const ref::Ray& ray, double t) {
    for (int i = 0; i < 30; ++i) {
        const dvec3 p = ray.origin + t * ray.dir;
        const double slope = glm::dot(shape.normal(p), ray.dir);
        if (std::abs(slope) < 1e-3) return std::nullopt;  // grazing: a silhouette pixel
        const double step = shape.distance(p) / slope;
        t -= step;
        if (std::abs(step) < 1e-14 * std::max(1.0, t)) return t;
    }
    return std::nullopt;
}

struct ShadingError {
    double max = 0, mean = 0;
    long pixels = 0;
};

// Pixels whose ray meets a smooth part of the mesh and the analytic surface,
// away from the silhouette (N.V >= 0.2 on the analytic surface): highlight
// m = 10, the spec example's material and light.
ShadingError shading_error(const Object& object, const Analytic& shape) {
    Scene scene;
    scene.display = {256, 160, 5, false};
    scene.camera.position = {0.8, 2.0, 4.5};
    Light light;
    light.direction = glm::normalize(dvec3(1, 1, 1));
    scene.lights = {light};
    Material material;  // highlight, C0 = (0.8, 0.2, 0.2), d = 0.5, w = 1, m = 10
    const ref::MeshIntersector mesh(geometry::make_mesh(object));
    ShadingError error;
    double sum = 0;
    for (int y = 0; y < scene.display.height; ++y) {
        for (int x = 0; x < scene.display.width; ++x) {
            const ref::Ray ray = ref::camera_ray(scene.camera, scene.display.width, scene.display.height, x, y);
            const auto hits = mesh.intersect_all(ray);
            if (hits.empty() || hits[0].part != 0) continue;
            const auto t = refine_hit(shape, ray, hits[0].t);
            if (!t) continue;
            const dvec3 P = ray.origin + *t * ray.dir;
            const ref::SurfacePoint exact{P, shape.normal(P), -ray.dir};
            if (glm::dot(exact.N, exact.V) < 0.2) continue;
            const ref::SurfacePoint meshed{ray.origin + hits[0].t * ray.dir, hits[0].N, -ray.dir};
            const dvec3 diff = glm::abs(ref::shade_opaque(material, scene.lights, meshed) -
                                        ref::shade_opaque(material, scene.lights, exact));
            const double worst = std::max({diff.x, diff.y, diff.z});
            error.max = std::max(error.max, worst);
            sum += worst;
            ++error.pixels;
        }
    }
    error.mean = error.pixels ? sum / error.pixels : 0;
    return error;
}

// docs/shapes.md states: with the default segments (cylinder 64, torus 128) the
// shading error of a cylinder or torus filling a good part of a 256 x 160 view
// stays below 5e-3 (a sixth of a 5-bit level, 1/31 = 0.032) where N.V >= 0.2.
TEST(ShapeMesh, DefaultTessellationShadesWithinTheStatedError) {
    Object cyl;
    cyl.shape = Shape::cylinder;
    cyl.axis = glm::normalize(dvec3(0.3, 1, 0.2));
    cyl.radius = 0.8, cyl.height = 1.6;
    Object tor;
    tor.shape = Shape::torus;
    tor.axis = glm::normalize(dvec3(0.2, 1, 0.5));
    tor.major_radius = 1.0, tor.minor_radius = 0.35;
    for (int segments : {16, 32, 64, 128}) {
        cyl.segments = tor.segments = segments;
        const ShadingError c = shading_error(cyl, cylinder_side(cyl.center, cyl.axis, cyl.radius));
        const ShadingError t = shading_error(tor, torus(tor.center, tor.axis, tor.major_radius, tor.minor_radius));
        std::printf("%3d segments: cylinder max %.3g mean %.3g (%ld px); torus max %.3g mean %.3g (%ld px)\n",
                    segments, c.max, c.mean, c.pixels, t.max, t.mean, t.pixels);
        EXPECT_GT(c.pixels, 3000);
        EXPECT_GT(t.pixels, 3000);
        if (segments == kDefaultSegments) {
            EXPECT_LE(c.max, 5e-3);
        }
        if (segments == kDefaultTorusSegments) {
            EXPECT_LE(t.max, 5e-3);
        }
    }
}

}  // namespace
}  // namespace m3055
