// One function per shape; see mesh.h for the conventions they all follow.
#include "geometry/mesh.h"

#include "numeric/angles.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace m3055::geometry {

namespace {

using numeric::kPi;

std::uint32_t add_vertex(Mesh& mesh, const dvec3& position, const dvec3& normal) {
    mesh.positions.push_back(position);
    mesh.normals.push_back(normal);
    return std::uint32_t(mesh.positions.size() - 1);
}

void add_triangle(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, int part) {
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
    mesh.parts.push_back(std::uint8_t(part));
}

// A flat quad centre +- h u +- h v with normal n = u x v (u, v unit, orthogonal;
// n given, so a plane keeps its loaded normal bit for bit): corners (-,-) (+,-)
// (+,+) (-,+), counter-clockwise around n.
void add_flat_quad(Mesh& mesh, const dvec3& centre, const dvec3& u, const dvec3& v, const dvec3& n, double h,
                   int part) {
    const std::uint32_t a = add_vertex(mesh, centre - h * u - h * v, n);
    const std::uint32_t b = add_vertex(mesh, centre + h * u - h * v, n);
    const std::uint32_t c = add_vertex(mesh, centre + h * u + h * v, n);
    const std::uint32_t d = add_vertex(mesh, centre - h * u + h * v, n);
    add_triangle(mesh, a, b, c, part);
    add_triangle(mesh, a, c, d, part);
}

// Unit vector at angle `angle` in the plane of T and B.
dvec3 radial(const AxisFrame& frame, double angle) {
    return std::cos(angle) * frame.t + std::sin(angle) * frame.b;
}

}  // namespace

AxisFrame axis_frame(const dvec3& axis) {
    const dvec3 a = axis;  // unit (the loader normalizes)
    const dvec3 m = glm::abs(a);
    const dvec3 e = m.x <= m.y && m.x <= m.z ? dvec3(1, 0, 0) : m.y <= m.z ? dvec3(0, 1, 0) : dvec3(0, 0, 1);
    const dvec3 t = glm::normalize(e - glm::dot(e, a) * a);
    return {t, glm::cross(a, t), a};
}

dvec3 rotate_xyz(const dvec3& v, const dvec3& rotation_deg) {
    const dvec3 r = rotation_deg * (kPi / 180.0);
    dvec3 p = v;
    p = {p.x, std::cos(r.x) * p.y - std::sin(r.x) * p.z, std::sin(r.x) * p.y + std::cos(r.x) * p.z};
    p = {std::cos(r.y) * p.x + std::sin(r.y) * p.z, p.y, -std::sin(r.y) * p.x + std::cos(r.y) * p.z};
    p = {std::cos(r.z) * p.x - std::sin(r.z) * p.y, std::sin(r.z) * p.x + std::cos(r.z) * p.y, p.z};
    return p;
}

// A square of side `size` in the plane through `center` with unit `normal`,
// its edges along the normal's axis frame T and B. Flat: two triangles are exact.
Mesh make_plane(const dvec3& center, const dvec3& normal, double size) {
    const AxisFrame frame = axis_frame(normal);
    Mesh mesh;
    add_flat_quad(mesh, center, frame.t, frame.b, frame.a, size / 2, 0);
    return mesh;
}

// Six flat faces, each with its own four vertices and normal (parts 0-5:
// +x, +y, +z, -x, -y, -z of the unrotated cube).
Mesh make_cube(const dvec3& center, double size, const dvec3& rotation_deg) {
    const dvec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const double h = size / 2;
    Mesh mesh;
    for (int face = 0; face < 6; ++face) {
        const int i = face % 3;
        const double sign = face < 3 ? 1.0 : -1.0;
        // u x v = +e_i: (y, z) for x, (z, x) for y, (x, y) for z; swapped for -e_i.
        dvec3 u = rotate_xyz(axes[(i + 1) % 3], rotation_deg);
        dvec3 v = rotate_xyz(axes[(i + 2) % 3], rotation_deg);
        if (sign < 0) std::swap(u, v);
        const dvec3 n = rotate_xyz(sign * axes[i], rotation_deg);
        add_flat_quad(mesh, center + h * n, u, v, n, h, face);
    }
    return mesh;
}

// Side: `segments` quads with the analytic radial normals (part 0); caps: fans
// with the axis normals (bottom part 1, top part 2), their own rim vertices.
Mesh make_cylinder(const dvec3& center, const dvec3& axis, double radius, double height, bool capped,
                   int segments) {
    const AxisFrame frame = axis_frame(axis);
    const dvec3 bottom = center - (height / 2) * frame.a, top = center + (height / 2) * frame.a;
    const std::uint32_t n = std::uint32_t(segments);
    Mesh mesh;
    for (std::uint32_t k = 0; k < n; ++k) {
        const dvec3 d = radial(frame, 2 * kPi * k / n);
        add_vertex(mesh, bottom + radius * d, d);  // 2k
        add_vertex(mesh, top + radius * d, d);     // 2k + 1
    }
    for (std::uint32_t k = 0; k < n; ++k) {
        const std::uint32_t b0 = 2 * k, t0 = 2 * k + 1, b1 = 2 * ((k + 1) % n), t1 = b1 + 1;
        add_triangle(mesh, b0, b1, t1, 0);
        add_triangle(mesh, b0, t1, t0, 0);
    }
    if (!capped) return mesh;
    for (int cap = 0; cap < 2; ++cap) {
        const dvec3 c = cap == 0 ? bottom : top;
        const dvec3 normal = cap == 0 ? -frame.a : frame.a;
        const std::uint32_t hub = add_vertex(mesh, c, normal);
        for (std::uint32_t k = 0; k < n; ++k) add_vertex(mesh, c + radius * radial(frame, 2 * kPi * k / n), normal);
        for (std::uint32_t k = 0; k < n; ++k) {
            const std::uint32_t r0 = hub + 1 + k, r1 = hub + 1 + (k + 1) % n;
            if (cap == 0)
                add_triangle(mesh, hub, r1, r0, 1);  // seen from below: clockwise around +A
            else
                add_triangle(mesh, hub, r0, r1, 2);
        }
    }
    return mesh;
}

// A grid of segments x segments quads over (phi around the axis, theta around
// the tube); P = c + R d(phi) + r n, n = cos(theta) d(phi) + sin(theta) A.
Mesh make_torus(const dvec3& center, const dvec3& axis, double major_radius, double minor_radius,
                int segments) {
    const AxisFrame frame = axis_frame(axis);
    const std::uint32_t n = std::uint32_t(segments);
    Mesh mesh;
    for (std::uint32_t i = 0; i < n; ++i) {
        const dvec3 d = radial(frame, 2 * kPi * i / n);
        for (std::uint32_t j = 0; j < n; ++j) {
            const double theta = 2 * kPi * j / n;
            const dvec3 normal = std::cos(theta) * d + std::sin(theta) * frame.a;
            add_vertex(mesh, center + major_radius * d + minor_radius * normal, normal);
        }
    }
    auto at = [n](std::uint32_t i, std::uint32_t j) { return (i % n) * n + j % n; };
    for (std::uint32_t i = 0; i < n; ++i) {
        for (std::uint32_t j = 0; j < n; ++j) {
            add_triangle(mesh, at(i, j), at(i + 1, j), at(i + 1, j + 1), 0);
            add_triangle(mesh, at(i, j), at(i + 1, j + 1), at(i, j + 1), 0);
        }
    }
    return mesh;
}

Mesh place_model(const model_file::Model& model, const dvec3& center, double size, const dvec3& rotation_deg) {
    const dvec3 middle = (model.lo + model.hi) * 0.5, extent = model.hi - model.lo;
    const double scale = size / std::max(extent.x, std::max(extent.y, extent.z));
    Mesh mesh;
    mesh.positions.reserve(model.positions.size());
    mesh.normals.reserve(model.normals.size());
    for (const dvec3& p : model.positions) mesh.positions.push_back(center + rotate_xyz((p - middle) * scale, rotation_deg));
    for (const dvec3& n : model.normals) mesh.normals.push_back(rotate_xyz(n, rotation_deg));
    mesh.indices = model.indices;
    mesh.parts = model.parts;
    mesh.groups = model.groups;
    return mesh;
}

Mesh make_mesh(const Object& object) {
    switch (object.shape) {
        case Shape::sphere: return {};
        case Shape::plane: return make_plane(object.center, object.axis, object.size);
        case Shape::cube: return make_cube(object.center, object.size, object.rotation_deg);
        case Shape::cylinder:
            return make_cylinder(object.center, object.axis, object.radius, object.height, object.capped,
                                 segments_of(object));
        case Shape::torus:
            return make_torus(object.center, object.axis, object.major_radius, object.minor_radius,
                              segments_of(object));
        case Shape::mesh:
            return object.model ? place_model(*object.model, object.center, object.size, object.rotation_deg) : Mesh{};
    }
    return {};
}

double bounding_radius(const Object& object) {
    switch (object.shape) {
        case Shape::sphere: return object.radius;
        case Shape::plane: return object.size * std::sqrt(0.5);
        case Shape::cube: return object.size * std::sqrt(0.75);
        case Shape::cylinder: return std::hypot(object.radius, object.height / 2);
        case Shape::torus: return object.major_radius + object.minor_radius;
        case Shape::mesh: {
            if (!object.model) return 0.0;
            const dvec3 extent = object.model->hi - object.model->lo;
            return object.size * 0.5 * glm::length(extent) / std::max(extent.x, std::max(extent.y, extent.z));
        }
    }
    return object.radius;
}

}  // namespace m3055::geometry
